"""Charts of an `ecoview bench` run: python3 bench_charts.py RESULTS_JSON OUT_DIR.

Embedded in the ecoview binary, which runs it with the system interpreter after a run."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.transforms import Bbox  # noqa: E402

MARKERS = {"uniform": "o", "psm": "s", "lispsm": "^", "cascades": "v", "dpsm": "D", "ipsm": "P", "silhouette": "<",
           "psm+silhouette": ">", "adaptive": "8", "volumes": "*", "hybrid": "p", "reference": "h", "auto": "X"}


def runs(results, sweep, **params):
    return [r for r in results["runs"]
            if r["params"].get("sweep") == sweep and all(r["params"].get(k) == v for k, v in params.items())]


def methods(rs):
    return sorted({r["params"]["method"] for r in rs}, key=lambda m: list(MARKERS).index(m) if m in MARKERS else 99)


def plot_lines(ax, lines, note=lambda ys: ""):
    """Each method's line (a dict method -> (xs, ys)). Where a line has another's values of y (auto
    where it chose the PSM: its times differ a little) it would hide under it: it is drawn dashed
    with open markers and labelled "auto = psm here", or "auto (= psm at 5 of 6)" where it has most of
    them."""
    drawn = {}
    for m, (xs, ys) in lines.items():
        shared = {o: sum(a == b for a, b in zip(ys, oys)) for o, oys in drawn.items() if len(oys) == len(ys)}
        same = max(shared, key=shared.get, default=None)
        label = m
        if same and shared[same] == len(ys):
            label = f"{m} = {same} here"
        elif same and 2 * shared[same] > len(ys):  # a line of its own that meets another now and then stays solid
            label = f"{m} (= {same} at {shared[same]} of {len(ys)})"
        style = dict(ls="--", mfc="none", ms=9) if label != m else {}
        ax.plot(xs, ys, marker=MARKERS.get(m, "o"), label=label + note(ys), **style)
        drawn[m] = ys


# Where a label may sit beside its point, in points from it: nearest first, then further out.
LABEL_OFFSETS = [(3, 3), (3, -9), (-3, 3), (-3, -9), (3, 12), (3, -18), (-3, 12), (-3, -18), (10, -3), (-10, -3),
                 (3, 21), (3, -27), (-3, 21), (-3, -27), (3, 30), (3, -36), (-3, 30), (-3, -36)]


def place_labels(ax, labels, fontsize=6):
    """Labels (x, y, text) beside their points, placed greedily in turn: each at the first offset
    where it stays inside the axes and covers no point and no label placed before it; where none is
    free, at the last offset tried, with a line to its point. Call it once the axes' limits and layout are final:
    it measures in the figure's pixels."""
    ax.figure.canvas.draw()
    renderer = ax.figure.canvas.get_renderer()
    taken = []
    for x, y in ((x, y) for x, y, _ in labels):  # the points' markers, a few pixels each way
        px, py = ax.transData.transform((x, y))
        taken.append(Bbox([[px - 3, py - 3], [px + 3, py + 3]]))
    for x, y, text in labels:
        for i, (dx, dy) in enumerate(LABEL_OFFSETS):
            last = i == len(LABEL_OFFSETS) - 1
            note = ax.annotate(text, (x, y), xytext=(dx, dy), textcoords="offset points", fontsize=fontsize,
                               ha="left" if dx >= 0 else "right",
                               arrowprops=dict(arrowstyle="-", lw=0.4, color="gray") if last else None)
            box = note.get_window_extent(renderer)
            inside = ax.bbox.x0 <= box.x0 and box.x1 <= ax.bbox.x1 and ax.bbox.y0 <= box.y0 and box.y1 <= ax.bbox.y1
            if last or (inside and not any(box.overlaps(t) for t in taken)):
                taken.append(box)
                break
            note.remove()


def tradeoff_chart(results, out):
    scenes = sorted({r["params"]["scene"] for r in runs(results, "tradeoff")})
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.5), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        rs = runs(results, "tradeoff", scene=scene)
        lines = {}
        for m in methods(rs):
            line = sorted((r for r in rs if r["params"]["method"] == m), key=lambda r: r["params"]["shadow_size"])
            lines[m] = ([r["figures"]["frame_ms"] for r in line], [100 * r["figures"]["err"] for r in line])
        plot_lines(ax, lines)
        # The front bench's summary lists (results.json's pareto_front): a scene is timed in one
        # sweep only (tradeoff or scenes), so its front is this sweep's own.
        front = [p for p in results["pareto_front"].get(scene, []) if p["sweep"] == "tradeoff"]
        ax.plot([p["frame_ms"] for p in front], [100 * p["err"] for p in front], color="gray", lw=6, alpha=0.25,
                label="Pareto front")
        ax.set(xscale="log", xlabel="frame_ms", ylabel="err (%)", title=f"Speed against accuracy: {scene}")
        ax.legend(fontsize=7)
    fig.tight_layout()
    for ax, scene in zip(axes[0], scenes):  # each map's size beside its point; the unsized methods' names
        place_labels(ax, [(r["figures"]["frame_ms"], 100 * r["figures"]["err"],
                           str(r["params"]["shadow_size"]) if r["params"]["shadow_size"] else r["params"]["method"])
                          for r in runs(results, "tradeoff", scene=scene)])
    fig.savefig(f"{out}/chart_tradeoff.png", dpi=100)


def equal_err_chart(results, out):
    """Per scene, each warped method's speed-up and texel ratio over the uniform map at its error;
    open markers where the uniform map's sizes only bound them."""
    rs = runs(results, "equal_err")
    fig, (speed_ax, texel_ax) = plt.subplots(1, 2, figsize=(12, 4.5))
    labels = {speed_ax: [], texel_ax: []}
    for scene in sorted({r["params"]["scene"] for r in rs}):
        for m in methods([r for r in rs if r["params"]["scene"] == scene]):
            line = sorted((r for r in rs if r["params"]["scene"] == scene and r["params"]["method"] == m),
                          key=lambda r: -r["figures"]["err"])
            errs = [100 * r["figures"]["err"] for r in line]
            for ax, key in ((speed_ax, "equal_err_speedup"), (texel_ax, "equal_err_texels")):
                drawn = ax.plot(errs, [r["figures"][key] for r in line], "-", label=f"{scene}: {m}")
                for r, e in zip(line, errs):
                    exact = r["params"]["bound"] == "equal"
                    ax.plot([e], [r["figures"][key]], marker=MARKERS.get(m, "o"), color=drawn[0].get_color(),
                            mfc=None if exact else "none")
                    labels[ax].append((e, r["figures"][key], str(r["params"]["shadow_size"]) +
                                       ("" if exact else " (" + r["params"]["bound"] + ")")))
    speed_ax.axhline(1, color="gray", ls=":", label="target: 1 (as fast as uniform)")
    texel_ax.axhline(16, color="gray", ls=":", label="target on the field: 16")
    speed_ax.set(xscale="log", yscale="log", xlabel="err (%) the method reaches (its map size marked)",
                 ylabel="uniform's frame_ms / the method's", title="Speed-up at equal error")
    texel_ax.set(xscale="log", yscale="log", xlabel="err (%) the method reaches (its map size marked)",
                 ylabel="uniform's texels / the method's", title="Texels saved at equal error")
    for ax in (speed_ax, texel_ax):
        ax.invert_xaxis()
        ax.legend(fontsize=6)
    fig.tight_layout()
    for ax, ax_labels in labels.items():
        place_labels(ax, ax_labels)
    fig.savefig(f"{out}/chart_equal_err.png", dpi=100)


def scenes_chart(results, out):
    """Per polygon scene, each method's err and frame time at one map size, as bars."""
    rs = runs(results, "scenes")
    scenes = list(dict.fromkeys(r["params"]["scene"] for r in rs))
    if not scenes:
        return
    fig, axes = plt.subplots(len(scenes), 2, figsize=(12, 3.2 * len(scenes)), squeeze=False)
    for (err_ax, ms_ax), scene in zip(axes, scenes):
        line = [r for r in rs if r["params"]["scene"] == scene]
        names = [r["params"]["method"] for r in line]
        for ax, values, label in ((err_ax, [100 * r["figures"]["err"] for r in line], "err (%)"),
                                  (ms_ax, [r["figures"]["frame_ms"] for r in line], "frame_ms")):
            bars = ax.barh(range(len(line)), values)
            ax.bar_label(bars, fmt="%.3g", fontsize=7)
            ax.set_yticks(range(len(line)), names, fontsize=8)
            ax.invert_yaxis()
            ax.set(xlabel=label, title=f"{scene} ({line[0]['params']['shadow_size']}² maps)")
    fig.tight_layout()
    fig.savefig(f"{out}/chart_scenes.png", dpi=100)


def stability_chart(results, out):
    fig, (err_ax, alias_ax, cross_ax) = plt.subplots(1, 3, figsize=(16, 4.5))
    rs = runs(results, "stability")
    errs, aliasing = {}, {}
    for m in methods(rs):
        line = sorted((r for r in rs if r["params"]["method"] == m), key=lambda r: r["params"]["light_view_deg"])
        deg = [r["params"]["light_view_deg"] for r in line]
        errs[m] = (deg, [100 * r["figures"]["err"] for r in line])
        lit = [(d, r["figures"]["alias_p95"]) for d, r in zip(deg, line) if r["figures"]["alias_p95"] > 0]
        aliasing[m] = ([d for d, _ in lit], [a for _, a in lit])
    plot_lines(err_ax, errs)
    plot_lines(alias_ax, aliasing)
    err_ax.set(xlabel="light-view angle (deg)", ylabel="err (%)", title="Error against the light direction (field)")
    alias_ax.set(xlabel="light-view angle (deg)", ylabel="alias_p95", yscale="log",
                 title="Aliasing against the light direction (field; none where nothing is lit)")
    rs = runs(results, "crossing")
    crossing = {}
    for m in methods(rs):
        line = sorted((r for r in rs if r["params"]["method"] == m), key=lambda r: r["params"]["light_offset_m"])
        crossing[m] = ([r["params"]["light_offset_m"] for r in line], [100 * r["figures"]["err"] for r in line])
    plot_lines(cross_ax, crossing)
    cross_ax.axvline(0, color="gray", ls=":")
    cross_ax.set_xscale("symlog", linthresh=1)
    offsets = sorted({r["params"]["light_offset_m"] for r in rs})
    cross_ax.set_xticks(offsets, [f"{o:g}" for o in offsets], fontsize=7)
    cross_ax.set(xlabel="point light ahead of the camera plane (m)", ylabel="err (%)",
                 title="A point light crossing the camera plane")
    for ax in (err_ax, alias_ax, cross_ax):
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{out}/chart_stability.png", dpi=100)


def flythrough_chart(results, out):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    rs = runs(results, "flythrough")
    lines = {}
    for m in methods(rs):
        line = sorted((r for r in rs if r["params"]["method"] == m), key=lambda r: r["params"]["frame"])
        lines[m] = ([r["params"]["t"] for r in line], [100 * r["figures"]["err"] for r in line])
    plot_lines(ax, lines, note=lambda ys: f" (worst {max(ys):.2f} %)")
    scene = rs[0]["params"]["scene"] if rs else ""
    ax.set(xlabel="t (s)", ylabel="err (%)", title=f"Error along the {scene} path")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{out}/chart_flythrough.png", dpi=100)


def main():
    results = json.load(open(sys.argv[1]))
    out = sys.argv[2]
    tradeoff_chart(results, out)
    equal_err_chart(results, out)
    scenes_chart(results, out)
    stability_chart(results, out)
    flythrough_chart(results, out)


main()
