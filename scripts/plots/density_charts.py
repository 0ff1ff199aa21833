"""Charts of an `ecoview density` run: python3 density_charts.py RESULTS_JSON OUT_DIR.

Embedded in the ecoview binary, which runs it with the system interpreter after a run."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def runs(results, sweep):
    return [r for r in results["runs"] if r["params"].get("sweep") == sweep]


def quality_chart(results, out):
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for splat in sorted({r["params"]["splat"] for r in runs(results, "quality")}):
        line = sorted((r for r in runs(results, "quality") if r["params"]["splat"] == splat), key=lambda r: r["params"]["k"])
        ms = [r["figures"]["frame_ms"] for r in line]
        left.plot(ms, [r["figures"]["psnr"] for r in line], "o-", label=f"splat {splat} px")
        right.plot(ms, [100 * r["figures"]["holes"] for r in line], "o-", label=f"splat {splat} px")
        for r in line:
            left.annotate(f"k={r['params']['k']}", (r["figures"]["frame_ms"], r["figures"]["psnr"]), fontsize=7)
    left.set(xlabel="frame_ms (points only)", ylabel="psnr (dB)", title="Quality against time")
    right.set(xlabel="frame_ms (points only)", ylabel="holes (%)", title="Holes against time")
    left.axhline(28, color="gray", ls=":")
    right.axhline(1, color="gray", ls=":")
    left.legend()
    right.legend()
    fig.tight_layout()
    fig.savefig(f"{out}/chart_quality.png", dpi=100)


def scale_chart(results, out):
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for geometry, marker in (("points", "o-"), ("polygons", "s--")):
        line = sorted((r for r in runs(results, "scale") if r["params"]["geometry"] == geometry),
                      key=lambda r: r["params"]["instances"])
        n = [r["params"]["instances"] for r in line]
        drawn = [r["figures"]["points"] if geometry == "points" else r["figures"]["triangles"] for r in line]
        left.loglog(n, drawn, marker, label=f"{geometry}: {'points' if geometry == 'points' else 'triangles'} drawn")
        right.loglog(n, [r["figures"]["frame_ms"] for r in line], marker, label=geometry)
    left.set(xlabel="instances", ylabel="drawn per frame", title="Points and polygons against instances")
    right.set(xlabel="instances", ylabel="frame_ms", title="Frame time against instances")
    left.legend()
    right.legend()
    fig.tight_layout()
    fig.savefig(f"{out}/chart_scale.png", dpi=100)


def thirds_chart(results, out):
    fig, ax = plt.subplots(figsize=(6, 4))
    line = runs(results, "quality")
    labels = [f"k={r['params']['k']}, s={r['params']['splat']}" for r in line]
    for i, third in enumerate(("near", "middle", "far")):
        ax.bar([x + 0.27 * i for x in range(len(line))], [r["figures"][f"pts_per_px_{third}"] for r in line], 0.27, label=third)
    ax.set_xticks([x + 0.27 for x in range(len(line))], labels, rotation=30, fontsize=7)
    ax.set(ylabel="points of the seen surface per covered pixel", title="Density in the nearest, middle, farthest third of the pixels")
    ax.legend()
    fig.tight_layout()
    fig.savefig(f"{out}/chart_thirds.png", dpi=100)


def main():
    results = json.load(open(sys.argv[1]))
    quality_chart(results, sys.argv[2])
    scale_chart(results, sys.argv[2])
    thirds_chart(results, sys.argv[2])


main()
