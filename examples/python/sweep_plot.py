#!/usr/bin/env python3
"""Sweep the contact stiffness of a case and plot the impact period T and the transient time T_p.

The same computation as

    vibroimpact sweep CASE --set supports[0].stiffness=log:100:100000:N

run in-process through the Python module (docs/python.md), drawn with matplotlib.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep_plot.py \
        examples/paper/free_impact_tip.toml --points 20 --out sweep.png
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402

import vibroimpact as vi  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", nargs="?", default=str(HERE.parent / "paper/free_impact_tip.toml"),
                        help="case file (TOML) with at least one support")
    parser.add_argument("--points", type=int, default=20, help="stiffness values, log-spaced")
    parser.add_argument("--low", type=float, default=100.0, help="lowest contact stiffness [N/m]")
    parser.add_argument("--high", type=float, default=1e5, help="highest contact stiffness [N/m]")
    parser.add_argument("--out", default="sweep.png", help="figure file")
    args = parser.parse_args()

    case = vi.load(args.case)
    result = vi.sweep(case, {"supports[0].stiffness": f"log:{args.low}:{args.high}:{args.points}"})
    table = result["table"]
    ok = table["status"] == "ok"
    kc = table["supports[0].stiffness_n_m"]  # a swept path's column carries its unit

    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(6, 6))
    top.semilogx(kc[ok], table["T_s"][ok] * 1e6, "o-")
    top.set_ylabel("T, period of impact vibrations [us]")
    bottom.semilogx(kc[ok], table["Tp_s"][ok] * 1e6, "s-", color="tab:red")
    bottom.set_ylabel("T_p, transient [us]")
    bottom.set_xlabel("contact stiffness K_c [N/m]")
    top.set_title(f"{case.name}: {len(kc)} points, {int(ok.sum())} ok")
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"{len(kc)} points ({int(ok.sum())} ok) in {result['summary']['wall_s']:.2f} s; figure in {args.out}")


if __name__ == "__main__":
    main()
