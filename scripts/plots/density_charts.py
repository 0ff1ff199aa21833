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
    """psnr and ssim of the points less those of the polygons at one sample a pixel (each against
    the 4×4-sample reference, over the same pixels), with the targets, and holes."""
    rs = runs(results, "quality")
    fig, (psnr_ax, ssim_ax, holes_ax) = plt.subplots(1, 3, figsize=(15, 4))
    for splat in sorted({r["params"]["splat"] for r in rs}):
        line = sorted((r for r in rs if r["params"]["splat"] == splat), key=lambda r: r["params"]["k"])
        ms = [r["figures"]["frame_ms"] for r in line]
        for ax, key in ((psnr_ax, "psnr"), (ssim_ax, "ssim")):
            gaps = [r["figures"][key] - r["figures"][f"{key}_polygons"] for r in line]
            ax.plot(ms, gaps, "o-", label=f"splat {splat} px")
            for r, gap in zip(line, gaps):
                ax.annotate(f"k={r['params']['k']}: {r['figures'][key]:.2f} vs {r['figures'][f'{key}_polygons']:.2f}",
                            (r["figures"]["frame_ms"], gap), fontsize=6)
        holes_ax.plot(ms, [100 * r["figures"]["holes"] for r in line], "o-", label=f"splat {splat} px")
    for ax, margin, unit in ((psnr_ax, 1.0, " dB"), (ssim_ax, 0.02, "")):
        ax.axhline(0, color="black", lw=1, label="as good as the polygons")
        ax.axhline(-margin, color="gray", ls=":", label=f"target: polygons − {margin:g}{unit}")
    holes_ax.axhline(1, color="gray", ls=":", label="target: 1 %")
    psnr_ax.set(xlabel="frame_ms (points only)", ylabel="psnr, points − polygons (dB)",
                title="PSNR against the 4×4-sample reference")
    ssim_ax.set(xlabel="frame_ms (points only)", ylabel="ssim, points − polygons",
                title="SSIM against the 4×4-sample reference")
    holes_ax.set(xlabel="frame_ms (points only)", ylabel="holes (%)", title="Holes against time")
    for ax in (psnr_ax, ssim_ax, holes_ax):
        ax.legend(fontsize=7)
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
        if geometry == "points" and line:
            # The targets: from the fewest plants to the most, points at most 1.5 times, frame time 2 times.
            left.axhline(1.5 * drawn[0], color="gray", ls=":", label="target: 1.5 × the points at the fewest")
            right.axhline(2 * line[0]["figures"]["frame_ms"], color="gray", ls=":", label="target: 2 × the frame at the fewest")
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
