// report.html's page script: draws each figure's interactive charts with uPlot from the JSON beside
// it (plot/chart_json.hpp), and records what happened on the page for the browser test
// (tests/browser/check_report.sh): each figure element gets data-drawn="1" once every panel of it has
// been drawn, the body element gets data-vi-figures / data-vi-drawn (counts) and data-vi-errors
// (errors and console.error calls; their text in the element #vi-errors). An animated beam (a figure
// of class vi-animation, plot/beam_animation.hpp) is drawn as SVG and played frame by frame; it gets
// data-drawn once its first frame is drawn and data-frames-shown counts the frames shown since. Runs before uPlot's own
// script, so that an error there is recorded too; draws on DOMContentLoaded. Writes nothing to the
// console itself but what it forwards from console.error.
(function () {
  'use strict';

  var errors = [];
  function note(text) {
    errors.push(String(text));
    if (document.body) {
      document.body.setAttribute('data-vi-errors', String(errors.length));
      var pre = document.getElementById('vi-errors');
      if (pre) pre.textContent = errors.join('\n');
    }
  }
  window.addEventListener('error', function (e) { note('error: ' + (e.message || e)); });
  window.addEventListener('unhandledrejection', function (e) { note('unhandled rejection: ' + e.reason); });
  var consoleError = console.error;
  console.error = function () {
    note('console.error: ' + Array.prototype.join.call(arguments, ' '));
    return consoleError.apply(console, arguments);
  };

  // The gnuplot figures' colours first (figures.hpp kColors), then more.
  var palette = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#8c564b', '#e377c2', '#7f7f7f', '#bcbd22', '#17becf'];
  var panelHeight = 380;   // [CSS px] of the plotting area and axes, without title and legend

  function fmt(v) {
    if (v === null || v === undefined || !isFinite(v)) return '–';
    var a = Math.abs(v);
    return (a !== 0 && (a < 1e-3 || a >= 1e6)) ? v.toExponential(4) : String(Number(v.toPrecision(5)));
  }

  // A tick label; a log axis passes null for the ticks it leaves unlabelled.
  function tick(v) { return v === null || v === undefined ? '' : fmt(v); }

  // Width of a y axis: room for its longest tick label and the axis label.
  function axisSize(u, values) {
    var longest = 0;
    (values || []).forEach(function (s) { longest = Math.max(longest, String(s).length); });
    return Math.max(50, 7 * longest + 30);
  }

  // Dashed vertical lines (marks) on top, shaded x intervals (bands) below the curves.
  function xDecor(panel, marks) {
    return function (u) {
      var list = marks ? panel.marks : panel.bands;
      if (!list.length) return;
      var ctx = u.ctx, top = u.bbox.top, h = u.bbox.height;
      ctx.save();
      ctx.beginPath();
      ctx.rect(u.bbox.left, top, u.bbox.width, h);
      ctx.clip();
      if (marks) {
        ctx.strokeStyle = '#777';
        ctx.lineWidth = uPlot.pxRatio;
        ctx.setLineDash([5 * uPlot.pxRatio, 4 * uPlot.pxRatio]);
        list.forEach(function (x) {
          var px = Math.round(u.valToPos(x, 'x', true));
          ctx.beginPath();
          ctx.moveTo(px, top);
          ctx.lineTo(px, top + h);
          ctx.stroke();
        });
      } else {
        ctx.fillStyle = 'rgba(0, 0, 0, 0.08)';
        list.forEach(function (b) {
          var x0 = u.valToPos(b[0], 'x', true), x1 = u.valToPos(b[1], 'x', true);
          ctx.fillRect(x0, top, Math.max(1, x1 - x0), h);
        });
      }
      ctx.restore();
    };
  }

  // A series' bars from 0 to y, each from x to xTo or barWidth about x, in its own points (not the
  // joined table's), as a uPlot paths builder.
  function barPaths(s) {
    return function (u, sidx) {
      var path = new Path2D(), scale = u.series[sidx].scale;
      var zero = u.valToPos(0, scale, true);
      s.x.forEach(function (x, i) {
        var y = s.y[i];
        if (y === null || x === null) return;
        var lo = s.xTo ? x : x - s.barWidth / 2, hi = s.xTo ? s.xTo[i] : x + s.barWidth / 2;
        if (hi === null) return;
        var x0 = u.valToPos(lo, 'x', true), x1 = u.valToPos(hi, 'x', true), py = u.valToPos(y, scale, true);
        path.rect(Math.min(x0, x1), Math.min(py, zero), Math.max(1, Math.abs(x1 - x0)), Math.abs(zero - py));
      });
      return { stroke: path, fill: path };
    };
  }

  // Interval bars (yLow to yHigh at each x, with caps) of the series shown, on top of the curves.
  function intervals(panel) {
    return function (u) {
      var ctx = u.ctx, cap = 4 * uPlot.pxRatio;
      ctx.save();
      ctx.beginPath();
      ctx.rect(u.bbox.left, u.bbox.top, u.bbox.width, u.bbox.height);
      ctx.clip();
      ctx.lineWidth = 1.5 * uPlot.pxRatio;
      ctx.strokeStyle = '#222';
      panel.series.forEach(function (s, k) {
        if (!s.yLow || !s.yHigh || !u.series[k + 1].show) return;
        var scale = u.series[k + 1].scale;
        s.x.forEach(function (x, i) {
          if (x === null || s.yLow[i] === null || s.yHigh[i] === null) return;
          var px = u.valToPos(x, 'x', true), lo = u.valToPos(s.yLow[i], scale, true), hi = u.valToPos(s.yHigh[i], scale, true);
          ctx.beginPath();
          ctx.moveTo(px, lo); ctx.lineTo(px, hi);
          ctx.moveTo(px - cap, lo); ctx.lineTo(px + cap, lo);
          ctx.moveTo(px - cap, hi); ctx.lineTo(px + cap, hi);
          ctx.stroke();
        });
      });
      ctx.restore();
    };
  }

  // The y range of a panel with bars or intervals: 0 (the bars' base) and every interval's ends in it.
  function barRange(panel) {
    return function (u, min, max) {
      var lo = Math.min(0, min), hi = Math.max(0, max);
      panel.series.forEach(function (s) {
        [s.y, s.yLow || [], s.yHigh || []].forEach(function (list) {
          list.forEach(function (v) { if (v !== null) { lo = Math.min(lo, v); hi = Math.max(hi, v); } });
        });
      });
      var pad = 0.05 * ((hi - lo) || 1);
      return [lo < 0 ? lo - pad : 0, hi + pad];
    };
  }

  // One uPlot chart for one panel; calls `drawn` after its first complete draw.
  function drawPanel(panel, box, width, drawn) {
    var tables = [], series = [{ label: panel.xLabel || 'x', value: function (u, v) { return fmt(v); } }];
    var groupColor = {}, groupFirst = {}, groupOf = [null], next = 0, points = 0;
    panel.series.forEach(function (s, k) {
      tables.push([s.x, s.y]);
      s.y.forEach(function (v) { if (v !== null) points++; });
      var color = s.color || (s.group && groupColor[s.group]) || palette[next++ % palette.length];
      if (s.group && !groupColor[s.group]) groupColor[s.group] = color;
      var onlyPoints = s.style === 'points', bars = s.style === 'bars';
      var opt = {
        label: s.label,
        stroke: color,
        width: onlyPoints ? 0 : 1.6,
        scale: s.right ? 'y2' : 'y',
        value: function (u, v) { return fmt(v); },
        points: { show: s.style !== 'lines' && !bars, size: 4.5, width: 1, stroke: color, fill: color }
      };
      if (onlyPoints) opt.paths = function () { return null; };
      if (bars) {
        opt.paths = barPaths(s);
        opt.fill = color + '99';
        opt.width = 1;
      }
      if (s.dash) opt.dash = [8, 5];
      series.push(opt);
      groupOf.push(s.group || null);
      if (s.group && groupFirst[s.group] === undefined) groupFirst[s.group] = k + 1;
    });
    if (tables.length === 0) throw new Error('a panel without series');
    var data = uPlot.join(tables);
    var axes = [
      { label: panel.xLabel, values: function (u, splits) { return splits.map(tick); } },
      { label: panel.yLabel, size: axisSize, values: function (u, splits) { return splits.map(tick); } }
    ];
    var scales = { x: { time: false }, y: {} };
    var boxed = panel.series.some(function (s) { return s.style === 'bars' || s.yLow; });
    if (boxed && !panel.logY) scales.y.range = barRange(panel);
    if (panel.xTicks && panel.xTicks.length) {
      axes[0].splits = function () { return panel.xTicks.map(function (t) { return t[0]; }); };
      axes[0].values = function (u, splits) {
        return splits.map(function (v) {
          var t = panel.xTicks.filter(function (p) { return p[0] === v; })[0];
          return t ? t[1] : '';
        });
      };
    }
    if (panel.logX) { scales.x.distr = 3; scales.x.log = 10; }
    if (panel.logY) { scales.y.distr = 3; scales.y.log = 10; }
    if (panel.y2Label) {
      scales.y2 = {};
      axes.push({ scale: 'y2', side: 1, label: panel.y2Label, size: axisSize, grid: { show: false },
                  values: function (u, splits) { return splits.map(tick); } });
    }
    var first = true, syncing = false;
    var opts = {
      title: panel.title || undefined,
      width: width,
      height: panelHeight,
      scales: scales,
      axes: axes,
      series: series,
      cursor: { drag: { x: true, y: true, uni: 40 } },
      hooks: {
        drawClear: [xDecor(panel, false)],
        draw: [xDecor(panel, true), intervals(panel), function () { if (first) { first = false; drawn(points); } }],
        // Series of one group share a legend entry: showing or hiding it applies to all of them.
        setSeries: [function (u, idx, o) {
          if (syncing || !o || o.show === undefined || !groupOf[idx]) return;
          syncing = true;
          for (var i = 1; i < groupOf.length; i++) {
            if (i !== idx && groupOf[i] === groupOf[idx]) u.setSeries(i, { show: o.show });
          }
          syncing = false;
        }]
      }
    };
    var u = new uPlot(opts, data, box);
    var rows = u.root.querySelectorAll('.u-legend .u-series');
    for (var i = 1; i < groupOf.length; i++) {
      if (groupOf[i] && groupFirst[groupOf[i]] !== i && rows[i]) rows[i].style.display = 'none';
    }
    if (panel.xMin !== null || panel.xMax !== null) {
      var x = data[0];
      u.setScale('x', { min: panel.xMin !== null ? panel.xMin : x[0], max: panel.xMax !== null ? panel.xMax : x[x.length - 1] });
    }
    return u;
  }

  function drawFigure(fig, plots) {
    var source = fig.querySelector('script.vi-chart-data');
    var box = fig.querySelector('div.vi-chart');
    var spec = JSON.parse(source.textContent);
    var pending = spec.panels.length, total = 0;
    var width = Math.max(320, box.clientWidth || fig.clientWidth || 900);
    spec.panels.forEach(function (panel) {
      var holder = document.createElement('div');
      holder.className = 'vi-panel';
      box.appendChild(holder);
      plots.push(drawPanel(panel, holder, width, function (points) {
        total += points;
        if (--pending === 0) {
          fig.setAttribute('data-drawn', '1');
          fig.setAttribute('data-points', String(total));
          fig.classList.add('vi-drawn');
          var done = document.querySelectorAll('figure[data-drawn="1"]').length;
          document.body.setAttribute('data-vi-drawn', String(done));
        }
      }));
    });
    var toggle = document.createElement('button');
    toggle.type = 'button';
    toggle.className = 'vi-toggle';
    toggle.textContent = 'gnuplot drawing (PNG)';
    toggle.addEventListener('click', function () { fig.classList.toggle('vi-show-png'); });
    box.appendChild(toggle);
  }

  // An SI prefix for values up to `largest` in magnitude, so that they read from 1 up: [factor, prefix].
  function prefix(largest) {
    var steps = [[1, ''], [1e3, 'm'], [1e6, '\u00b5'], [1e9, 'n'], [1e12, 'p']];
    for (var i = 0; i < steps.length; i++) {
      if (largest * steps[i][0] >= 1) return steps[i];
    }
    return steps[steps.length - 1];
  }

  var svgNs = 'http://www.w3.org/2000/svg';
  function svgElement(name, attrs, parent) {
    var e = document.createElementNS(svgNs, name);
    Object.keys(attrs).forEach(function (k) { e.setAttribute(k, String(attrs[k])); });
    if (parent) parent.appendChild(e);
    return e;
  }

  // The deflected beam of every frame in turn (about 12 frames a second), with play/pause and a slider.
  function drawAnimation(fig) {
    var d = JSON.parse(fig.querySelector('script.vi-animation-data').textContent);
    var box = fig.querySelector('div.vi-beam');
    var nodes = d.x.length, frames = d.v.length;
    if (nodes < 2 || frames < 1) throw new Error('an animation without nodes or frames');
    var vmax = 0, xmax = 0, tmax = 0;
    d.v.forEach(function (row) { row.forEach(function (v) { vmax = Math.max(vmax, Math.abs(v)); }); });
    d.surfaces.forEach(function (s) { vmax = Math.max(vmax, Math.abs(s[1])); });
    d.x.forEach(function (x) { xmax = Math.max(xmax, Math.abs(x)); });
    d.t.forEach(function (t) { tmax = Math.max(tmax, Math.abs(t)); });
    if (vmax === 0) vmax = 1;
    var xp = prefix(xmax), vp = prefix(vmax), tp = prefix(tmax);
    var W = 900, H = 360, left = 80, right = 20, top = 20, bottom = 50;
    var x0 = d.x[0], x1 = d.x[nodes - 1];
    function px(x) { return left + (x - x0) / ((x1 - x0) || 1) * (W - left - right); }
    function py(v) { return top + (1 - (v + 1.1 * vmax) / (2.2 * vmax)) * (H - top - bottom); }
    var svg = svgElement('svg', { viewBox: '0 0 ' + W + ' ' + H, role: 'img' }, box);
    svgElement('rect', { x: left, y: top, width: W - left - right, height: H - top - bottom, fill: 'none', stroke: '#999' }, svg);
    svgElement('line', { x1: left, x2: W - right, y1: py(0), y2: py(0), stroke: '#bbb', 'stroke-dasharray': '4 4' }, svg);
    d.surfaces.forEach(function (s) {
      svgElement('line', { x1: px(s[0]) - 12, x2: px(s[0]) + 12, y1: py(s[1]), y2: py(s[1]), stroke: '#555', 'stroke-width': 3 }, svg);
    });
    [-vmax, 0, vmax].forEach(function (v) {
      var label = svgElement('text', { x: left - 6, y: py(v) + 4, 'text-anchor': 'end', 'font-size': 12 }, svg);
      label.textContent = fmt(v * vp[0]);
    });
    [x0, x1].forEach(function (x) {
      var label = svgElement('text', { x: px(x), y: H - bottom + 16, 'text-anchor': 'middle', 'font-size': 12 }, svg);
      label.textContent = fmt(x * xp[0]);
    });
    svgElement('text', { x: (left + W - right) / 2, y: H - 12, 'text-anchor': 'middle', 'font-size': 13 }, svg).textContent =
      'x along the beam [' + xp[1] + 'm]';
    svgElement('text', { x: 16, y: (top + H - bottom) / 2, 'text-anchor': 'middle', 'font-size': 13,
                         transform: 'rotate(-90 16 ' + (top + H - bottom) / 2 + ')' }, svg).textContent = 'deflection [' + vp[1] + 'm]';
    var line = svgElement('polyline', { fill: 'none', stroke: '#1f77b4', 'stroke-width': 3 }, svg);
    var clock = svgElement('text', { x: W - right - 6, y: top + 18, 'text-anchor': 'end', 'font-size': 14 }, svg);
    var controls = document.createElement('div');
    controls.className = 'vi-controls';
    var button = document.createElement('button');
    button.type = 'button';
    button.textContent = 'pause';
    var slider = document.createElement('input');
    slider.type = 'range';
    slider.min = '0';
    slider.max = String(frames - 1);
    slider.value = '0';
    controls.appendChild(button);
    controls.appendChild(slider);
    box.appendChild(controls);
    var shown = {}, count = 0, frame = 0, timer = null;
    function show(k) {
      frame = k;
      var row = d.v[k], points = [];
      for (var i = 0; i < nodes; i++) points.push(px(d.x[i]).toFixed(1) + ',' + py(row[i]).toFixed(1));
      line.setAttribute('points', points.join(' '));
      clock.textContent = 't = ' + fmt(d.t[k] * tp[0]) + ' ' + tp[1] + 's';
      slider.value = String(k);
      if (!shown[k]) { shown[k] = true; count++; }
      fig.setAttribute('data-frames-shown', String(count));
    }
    function play() { timer = setInterval(function () { show((frame + 1) % frames); }, 80); button.textContent = 'pause'; }
    function pause() { clearInterval(timer); timer = null; button.textContent = 'play'; }
    button.addEventListener('click', function () { if (timer) pause(); else play(); });
    slider.addEventListener('input', function () { pause(); show(Number(slider.value)); });
    show(0);
    fig.setAttribute('data-drawn', '1');
    fig.setAttribute('data-points', String(nodes * frames));
    fig.setAttribute('data-frames', String(frames));
    fig.classList.add('vi-drawn');
    document.body.setAttribute('data-vi-drawn', String(document.querySelectorAll('figure[data-drawn="1"]').length));
    if (frames > 1) play();
  }

  function start() {
    var body = document.body;
    var figures = document.querySelectorAll('figure');
    body.setAttribute('data-vi-figures', String(figures.length));
    body.setAttribute('data-vi-drawn', '0');
    body.setAttribute('data-vi-errors', String(errors.length));
    if (typeof uPlot === 'undefined') { note('uPlot did not load'); return; }
    var plots = [];
    Array.prototype.forEach.call(figures, function (fig) {
      if (fig.querySelector('script.vi-animation-data')) {
        try {
          drawAnimation(fig);
        } catch (e) {
          note('animation ' + fig.id + ': ' + e);
        }
        return;
      }
      if (!fig.querySelector('script.vi-chart-data')) return;   // a figure without charts: its PNG alone
      try {
        drawFigure(fig, plots);
      } catch (e) {
        note('figure ' + fig.id + ': ' + e);
      }
    });
    var timer = null;
    window.addEventListener('resize', function () {
      clearTimeout(timer);
      timer = setTimeout(function () {
        plots.forEach(function (u) {
          var w = u.root.parentNode.parentNode.clientWidth;
          if (w > 0) u.setSize({ width: Math.max(320, w), height: panelHeight });
        });
      }, 150);
    });
  }

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})();
