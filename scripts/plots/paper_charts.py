"""Charts of an `ecoview bench --suite paper` run: python3 paper_charts.py RESULTS_JSON OUT_DIR.

Embedded in the ecoview binary, which runs it with the system interpreter after a run."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def bias_chart(results, out):
    """The inverted light's bias sweep: acne and leak against the constant in each depth format,
    and against the slope in 32-bit float."""
    rs = [r for r in results["runs"] if r["params"].get("figure") == "bias"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    default_slope = min((r["params"]["bias_slope"] for r in rs), key=lambda s: abs(s - 2.0), default=2.0)
    default_constant = min((r["params"]["bias_constant"] for r in rs), key=lambda c: abs(c - 4.0), default=4.0)
    for ax, swept, fixed, fixed_value, label in (
            (axes[0], "bias_constant", "bias_slope", default_slope, "--bias-constant (depth steps)"),
            (axes[1], "bias_slope", "bias_constant", default_constant, "--bias-slope")):
        for depth, style in (("16", ":"), ("24", "--"), ("32f", "-")):
            line = sorted((r for r in rs if r["params"][fixed] == fixed_value and r["params"].get("shadow_depth", "32f") == depth),
                          key=lambda r: r["params"][swept])
            if not line:
                continue
            # A symlog axis shows 0 beside the large values the sweep goes to.
            xs = [r["params"][swept] for r in line]
            for key, marker in (("acne", "o"), ("leak", "s")):
                ax.plot(xs, [100 * r["figures"][key] for r in line], marker + style, label=f"{key}, {depth}")
        ax.set_xscale("symlog", linthresh=1)
        ax.set(xlabel=f"{label}; {fixed.replace('bias_', '')} at {fixed_value:g}", ylabel="% of surface pixels",
               title="The light behind the viewer: PSM 1024² on the field")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{out}/chart_bias.png", dpi=100)


def depth_chart(results, out):
    """The depth formats: acne and leak against the light's angle to the view, uniform and PSM."""
    rs = [r for r in results["runs"] if r["params"].get("figure") == "depth"]
    methods = sorted({r["params"]["method"] for r in rs})
    fig, axes = plt.subplots(1, 2, figsize=(11, 4), squeeze=False)
    for ax, key in zip(axes[0], ("acne", "leak")):
        for method, colour in zip(methods, ("tab:blue", "tab:orange", "tab:green")):
            for depth, style in (("16", "o:"), ("24", "s--"), ("32f", "^-")):
                line = sorted((r for r in rs if r["params"]["method"] == method and r["params"]["shadow_depth"] == depth),
                              key=lambda r: r["params"]["light_view_deg"])
                ax.plot([r["params"]["light_view_deg"] for r in line], [100 * r["figures"][key] for r in line], style,
                        color=colour, label=f"{method}, {depth}")
        ax.set(xlabel="light to view (°): 0 from behind the camera, 180 into it", ylabel=f"{key}, % of surface pixels",
               title=f"{key} in each depth format: field, 1024², default bias")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{out}/chart_depth.png", dpi=100)


def main():
    results = json.load(open(sys.argv[1]))
    bias_chart(results, sys.argv[2])
    depth_chart(results, sys.argv[2])


main()
