#!/usr/bin/env bash
# The interactive report pages in a real browser: generates report.html with `vibroimpact paper` (a
# coarse run), `vibroimpact switch-report` (the example switch) and uq.html with `vibroimpact uq` (a
# small Sobol study of the switch's pull-in), loads each in headless Chromium
# and fails unless every <figure> reports its charts drawn (data-drawn="1", set by the page script
# src/plot/report_charts.js from uPlot's draw hook, with points in it) and the page recorded no error
# or console.error, and Chromium logged no console message; the paper and switch pages' animated beam
# must have played (more than one frame shown). Then checks that it can fail: five broken copies of
# the paper page (a chart whose drawing throws, a console.error, a figure without its chart, an
# animation that stays on its first frame, an animation whose data does not parse) must each be rejected.
#
#   tests/browser/check_report.sh VIBROIMPACT SOURCE_DIR
#
# Needs the Debian package chromium (scripts/install-deps installs it); without it the check fails.
set -euo pipefail

exe=${1:?usage: check_report.sh VIBROIMPACT SOURCE_DIR}
src=${2:?usage: check_report.sh VIBROIMPACT SOURCE_DIR}
browser=${CHROMIUM:-}
if [ -z "$browser" ]; then
  browser=$(command -v chromium || command -v chromium-browser || true)
fi
if [ -z "$browser" ]; then
  echo "check_report: no chromium on PATH: install the Debian package chromium (scripts/install-deps does)" >&2
  exit 1
fi
if [ ! -x "$browser" ]; then
  echo "check_report: CHROMIUM=$browser is not an executable" >&2
  exit 1
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Loads a page, prints its rendered DOM into $tmp/dom.html and Chromium's log into $tmp/log.txt.
load() {
  rm -rf "$tmp/profile"
  # A fresh profile; --no-sandbox because CI runs as root; the virtual time budget lets the page's
  # scripts run to the end without waiting in real time. timeout: a hung browser fails, not blocks.
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --no-first-run --no-default-browser-check \
    --disable-extensions --user-data-dir="$tmp/profile" --enable-logging=stderr --v=0 \
    --virtual-time-budget=30000 --window-size=1280,900 --dump-dom "file://$1" >"$tmp/dom.html" 2>"$tmp/log.txt"
}

# An attribute of the <body> element of the dumped page ("" if absent).
body_attribute() {
  grep -o '<body[^>]*>' "$tmp/dom.html" | head -n 1 | grep -o "$1=\"[^\"]*\"" | sed 's/.*="\(.*\)"/\1/' || true
}

# 0 when the page drew every figure without an error; otherwise prints why and returns 1.
check_page() {
  local page=$1 name=$2
  if ! load "$page"; then
    echo "$name: chromium failed:" >&2
    tail -n 20 "$tmp/log.txt" >&2
    return 1
  fi
  local figures drawn with_points errors body_figures body_drawn problems=0
  figures=$(grep -o '<figure[ >]' "$tmp/dom.html" | wc -l)
  drawn=$(grep -o '<figure[^>]*data-drawn="1"' "$tmp/dom.html" | wc -l)
  with_points=$(grep -o '<figure[^>]*data-points="[1-9][0-9]*"' "$tmp/dom.html" | wc -l)
  body_figures=$(body_attribute data-vi-figures)
  body_drawn=$(body_attribute data-vi-drawn)
  errors=$(body_attribute data-vi-errors)
  echo "$name: $figures figures, $drawn drawn ($with_points with points); page says figures=${body_figures:-?} drawn=${body_drawn:-?} errors=${errors:-?}"
  if [ "$figures" -eq 0 ]; then
    echo "$name: no figures on the page" >&2
    problems=1
  fi
  if [ "$drawn" -ne "$figures" ] || [ "$with_points" -ne "$figures" ] || [ "${body_drawn:-}" != "$figures" ]; then
    echo "$name: not every figure was drawn with points" >&2
    problems=1
  fi
  if [ "${errors:-}" != "0" ]; then
    echo "$name: the page recorded errors (or its script did not run):" >&2
    sed -n 's/.*<pre id="vi-errors">\([^<]*\)<\/pre>.*/\1/p' "$tmp/dom.html" >&2
    problems=1
  fi
  # Chromium's own log of the page's console (uncaught exceptions too). It logs every level alike, and
  # the page writes nothing to the console, so any console line is a failure.
  if grep -q ':CONSOLE' "$tmp/log.txt"; then
    echo "$name: console messages in Chromium's log:" >&2
    grep ':CONSOLE' "$tmp/log.txt" >&2
    problems=1
  fi
  return $problems
}

# 0 when the last page loaded (check_page) has an animated beam that played: a <figure> of class
# vi-animation with several frames (data-frames) of which more than one was shown (data-frames-shown).
check_animation() {
  local name=$1 tag frames shown
  tag=$(grep -o '<figure[^>]*vi-animation[^>]*>' "$tmp/dom.html" | head -n 1 || true)
  if [ -z "$tag" ]; then
    echo "$name: no animated beam (figure.vi-animation) on the page" >&2
    return 1
  fi
  frames=$(echo "$tag" | grep -o 'data-frames="[0-9]*"' | grep -o '[0-9]*' || true)
  shown=$(echo "$tag" | grep -o 'data-frames-shown="[0-9]*"' | grep -o '[0-9]*' || true)
  echo "$name: animated beam with ${frames:-?} frames, ${shown:-0} shown"
  if [ -z "$frames" ] || [ "$frames" -lt 2 ] || [ -z "$shown" ] || [ "$shown" -lt 2 ]; then
    echo "$name: the animated beam did not play (frames=${frames:-none}, shown=${shown:-none})" >&2
    return 1
  fi
}

status=0
"$exe" paper --out "$tmp/paper" --positions 8 --modal-positions 20 --prestress-points 6 --scan-horizon "150 us" --quiet >/dev/null
check_page "$tmp/paper/report.html" "paper report.html" || status=1
check_animation "paper report.html" || status=1
"$exe" switch-report "$src/examples/switch/cantilever_switch.toml" --out "$tmp/switch" >/dev/null
check_page "$tmp/switch/report.html" "switch-report report.html" || status=1
check_animation "switch-report report.html" || status=1
# uq.html: histograms (bars from bin to bin) and Sobol bar charts with their interval bars.
"$exe" uq "$src/examples/switch/cantilever_switch.toml" --analysis pullin --vary 'beam.thickness=normal:2um:0.05um' \
  --vary 'electrodes[0].gap=normal:2um:0.05um' --spec 'pullin_voltage_v<=60' --sensitivity --samples 32 \
  --method sobol --bootstrap 200 --threads 1 --progress none --out "$tmp/uq" >/dev/null
check_page "$tmp/uq/uq.html" "uq uq.html" || status=1

# The check must be able to fail: a chart whose drawing throws, a console.error, a figure left
# without its chart, an animation that does not play and one whose data is broken must each be rejected.
sed 's/new uPlot(opts, data, box)/new uPlot(opts, data, box).no.such/' \
  "$tmp/paper/report.html" >"$tmp/paper/broken_draw.html"
sed 's#<pre id="vi-errors"></pre>#<pre id="vi-errors"></pre><script>document.addEventListener("DOMContentLoaded", function () { console.error("deliberate"); });</script>#' \
  "$tmp/paper/report.html" >"$tmp/paper/broken_console.html"
sed '0,/class="vi-chart-data"/s//class="vi-chart-none"/' "$tmp/paper/report.html" >"$tmp/paper/broken_missing.html"
# An animated beam that never moves past its first frame, and one whose data does not parse.
sed 's/timer = setInterval(/timer = (function () { return 0; })(/' "$tmp/paper/report.html" >"$tmp/paper/broken_still.html"
sed 's/class="vi-animation-data">{/class="vi-animation-data">{{/' "$tmp/paper/report.html" >"$tmp/paper/broken_animation.html"
for broken in broken_draw broken_console broken_missing broken_still broken_animation; do
  if cmp -s "$tmp/paper/report.html" "$tmp/paper/$broken.html"; then
    echo "$broken: could not break the page (its script changed?); update tests/browser/check_report.sh" >&2
    status=1
  elif check_page "$tmp/paper/$broken.html" "$broken.html (must be rejected)" 2>"$tmp/why.txt" &&
       check_animation "$broken.html (must be rejected)" 2>>"$tmp/why.txt"; then
    echo "$broken.html: a broken page passed the check" >&2
    status=1
  else
    echo "$broken.html: rejected, as it must be: $(head -n 1 "$tmp/why.txt")"
  fi
done
exit $status
