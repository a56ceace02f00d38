"""The paper's Fig. 2 from Python: the eccentricity of the contact ellipse against the
curvature ratio A1/B1 for several speeds M_R (nu = 0.2 as in the paper), from one
sweep_ellipses call over an 8 x 200 grid.

    python examples/python/fig2.py [OUT.svg]

Draws the chart with matplotlib when it is installed (pip install "./python[plot]"; OUT.svg,
default fig2_python.svg), else prints the table (M_R, A1/B1, e, bound on e) as CSV.
"""

import sys

import numpy as np

import moving_hertz as mh

SPEEDS = np.array([0.0, 0.3, 0.5, 0.7, 0.9, 0.95, 0.99, 0.999])
RATIOS = np.arange(1, 201) / 200  # A1/B1 = 0.005 ... 1


def main(out="fig2_python.svg"):
    r = mh.sweep_ellipses(0.2, speed=SPEEDS[:, None], ratio=RATIOS)
    assert r.ok.all(), r.messages[~r.ok]
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("M_R,A1/B1,e,e_error")
        for i, mr in enumerate(SPEEDS):
            for j, ratio in enumerate(RATIOS):
                print(f"{mr},{ratio},{float(r.e[i, j])!r},{float(r.e_error[i, j])!r}")
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for i, mr in enumerate(SPEEDS):
        ax.plot(RATIOS, r.e[i], label=f"M_R = {mr}")
    ax.set(xlabel="A1/B1", ylabel="eccentricity e", xlim=(0, 1), ylim=(0, 1),
           title="Eccentricity against A1/B1 (nu = 0.2), after the paper's Fig. 2")
    ax.legend(fontsize="small")
    fig.savefig(out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(*sys.argv[1:])
