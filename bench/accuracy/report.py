#!/usr/bin/env python3
"""Turns bench_accuracy's CSV files into docs/accuracy.md's charts and tables.

    report.py --data DIR --images DIR --template accuracy.md.in --out docs/accuracy.md

The template is Markdown with lines of the form `<!-- generated: NAME -->`;
each is replaced by the block NAME (a table or a list of charts), so the prose
stays hand-written while every number and picture comes from one run.
Charts are matplotlib PNGs (Debian's python3-matplotlib).
"""
import argparse
import csv
import math
import os
import re
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

# Per sweep: the error metric the speed/error charts and the failure map use,
# its label, and the threshold above which a method counts as failing.
SWEEPS = {
    "ao": {"metric": "rmse", "label": "AO RMSE", "threshold": 0.05},
    "normals": {"metric": "angle_p95", "label": "95th-percentile angular error (deg)", "threshold": 30.0},
    "fxaa": {"metric": "rmse", "label": "RGB RMSE vs 16x16 supersampling", "threshold": 0.03},
    "dof": {"metric": "rmse", "label": "RGB RMSE vs thin-lens reference", "threshold": 0.03},
    "transparency": {"metric": "rmse", "label": "RGB RMSE vs every crossing in depth order", "threshold": 0.02},
}

# Settings that equal each pass's default: the failure map and the
# edge/interior tables use these. Matched against the CSV's `setting` text; a
# method without an entry uses its median-quality setting.
DEFAULT_SETTINGS = {
    ("ao", "horizon"): "slices=4 steps=8",
    ("ao", "hemisphere"): "samples=16",
    ("ao", "horizon full resolution"): "slices=4 steps=8",
    ("ao", "hemisphere full resolution"): "samples=16",
    ("ao", "ray traced (cosine)"): "samples=16",
    ("ao", "lineao"): "samples=16",
    ("ao", "pointao"): "samples=16",
    ("ao", "sao"): "taps=16",
    ("ao", "point list"): "closed form",
    ("ao", "EDL"): "radius=1 scales=2",
    ("ao", "EDL (strength 0.1)"): "radius=1 scales=2",
    ("fxaa", "FXAA"): "preset 12",
    ("fxaa", "SSAA"): "2x2",
    ("dof", "SSDoF disc"): "samples 64",
    ("transparency", "layers + ColorMapping"): "K=4",
}


def _value(rows, region, metric):
    for r in rows:
        if r["region"] == region and r["metric"] == metric and math.isfinite(r["value"]):
            return r["value"]
    return math.nan


# The failure map's rule per sweep: which methods it judges, what it counts as
# failing (stated in the page), and the value it quotes. Rules that compare
# with a baseline (FXAA against its aliased input, SSDoF against doing
# nothing) judge whether the method does its job, not only the absolute error:
# a method that leaves the error where it was fails even when that error is
# small. `judge(own, base, floor)` gets the rows of one scene.
FAILURE_RULES = {
    "ao": {
        "methods": ["horizon", "hemisphere", "horizon points", "hemisphere points", "lineao", "pointao", "sao",
                    "point list", "EDL", "EDL (strength 0.1)"],
        "rule": "RMSE over geometry pixels > 0.05",
        "panels": "SSAO or EDL | reference | 4 × |error| (white = 0.25 or more)",
        "judge": lambda own, base, floor: _value(own, "all", "rmse") > 0.05,
        "quote": lambda own, base, floor: f"{_value(own, 'all', 'rmse'):.3f}",
    },
    "normals": {
        "methods": ["extrapolated", "central", "nearest"],
        "rule": "interior median > 5°, or 95th percentile over all geometry > 30°",
        "panels": "reconstructed | captured geometric normals (RGB = 0.5 + 0.5 n) | angular error (white = 45° or more)",
        "judge": lambda own, base, floor: _value(own, "interior", "angle_median") > 5.0
        or _value(own, "all", "angle_p95") > 30.0,
        "quote": lambda own, base, floor: f"{_value(own, 'interior', 'angle_median'):.2g}° / "
        f"{_value(own, 'all', 'angle_p95'):.3g}°",
    },
    "fxaa": {
        "methods": ["FXAA"],
        "baseline": "1 spp",
        "panels": "1 spp input | FXAA 12 | 16 × 16 reference (centre crop, magnified)",
        "rule": "RMSE above 90 % of the 1-sample input's (FXAA removes less than a tenth of the aliasing) "
        "while above 0.005, or RMSE above 0.02",
        "judge": lambda own, base, floor: (_value(own, "all", "rmse") > 0.9 * _value(base, "all", "rmse")
                                           and _value(own, "all", "rmse") > 0.005)
        or _value(own, "all", "rmse") > 0.02,
        "quote": lambda own, base, floor: f"{_value(own, 'all', 'rmse'):.4f} "
        f"({_value(own, 'all', 'rmse') / _value(base, 'all', 'rmse'):.0%} of the 1-spp error)",
    },
    "transparency": {
        "methods": ["layers + ColorMapping"],
        "settings": ["K=1", "K=2", "K=4", "K=8"],
        "rule": "RGB RMSE over covered pixels > 0.02 (fewer layers than the surfaces a ray crosses)",
        "panels": "",
        "judge": lambda own, base, floor: _value(own, "all", "rmse") > 0.02,
        "quote": lambda own, base, floor: f"{_value(own, 'all', 'rmse'):.3f} (beyond K: {_value(own, 'beyond K', 'rmse'):.3f})",
    },
    "dof": {
        "methods": ["SSDoF disc", "SSDoF hexagon"],
        "baseline": "sharp",
        "floor": "lens only",
        "panels": "SSDoF disc 64 | thin-lens reference | 4 × |error| (centre crop, magnified)",
        "rule": "removes less than half of the removable error (RMSE − floor > 0.5 × (sharp − floor), "
        "floor = the thin lens without pixel jitter) while more than 0.005 above the floor, or RMSE > 0.03",
        "judge": lambda own, base, floor: (
            (_value(own, "all", "rmse") - _value(floor, "all", "rmse")
             > 0.5 * (_value(base, "all", "rmse") - _value(floor, "all", "rmse"))
             and _value(own, "all", "rmse") - _value(floor, "all", "rmse") > 0.005)
            or _value(own, "all", "rmse") > 0.03),
        "quote": lambda own, base, floor: f"{_value(own, 'all', 'rmse'):.4f} "
        f"({(_value(own, 'all', 'rmse') - _value(floor, 'all', 'rmse')) / max(1e-12, _value(base, 'all', 'rmse') - _value(floor, 'all', 'rmse')):.0%} "
        "of the removable error left)",
    },
}


def save_png(fig, path):
    """Saves a chart as a 64-colour palette PNG: a third of the size of the
    true-colour file for flat-coloured charts, which keeps the committed page light."""
    import io
    from PIL import Image
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    plt.close(fig)
    buf.seek(0)
    Image.open(buf).convert("RGB").quantize(colors=64).save(path, optimize=True)


def shrink_pictures(image_dir, limit=60_000):
    """Failure pictures above `limit` bytes become 256-colour palette PNGs
    (dithered): enough to see the failure, small enough to commit."""
    from PIL import Image
    for name in os.listdir(image_dir):
        path = os.path.join(image_dir, name)
        if name.endswith(".png") and os.path.getsize(path) > limit:
            Image.open(path).convert("RGB").quantize(colors=256).save(path + ".tmp.png", optimize=True)
            if os.path.getsize(path + ".tmp.png") < os.path.getsize(path):
                os.replace(path + ".tmp.png", path)
            else:
                os.remove(path + ".tmp.png")


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def load(data_dir):
    rows = []
    for name in sorted(os.listdir(data_dir)):
        if not name.endswith(".csv"):
            continue
        with open(os.path.join(data_dir, name), newline="") as f:
            for r in csv.DictReader(f):
                for k in ("knob_value", "quality", "ms_per_mpix", "value"):
                    r[k] = number(r[k])
                rows.append(r)
    return rows


def pareto(points):
    """Points (time, error) not beaten on both axes, sorted by time."""
    front, best = [], math.inf
    for t, e in sorted(p for p in points if math.isfinite(p[0]) and math.isfinite(p[1])):
        if e < best:
            front.append((t, e))
            best = e
    return front


def timed(rows):
    return [r for r in rows if math.isfinite(r["ms_per_mpix"]) and r["ms_per_mpix"] > 0]


def speed_error_chart(rows, sweep, scene, out_dir):
    spec = SWEEPS[sweep]
    sel = [r for r in timed(rows) if r["sweep"] == sweep and r["scene"] == scene and r["region"] == "all"
           and r["metric"] == spec["metric"] and math.isfinite(r["value"])]
    if not sel:
        return None
    by_method = defaultdict(list)
    for r in sel:
        by_method[r["method"]].append(r)
    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=80)
    markers = "osD^v<>phX*"
    for k, (method, pts) in enumerate(sorted(by_method.items())):
        pts.sort(key=lambda r: (r["quality"], r["ms_per_mpix"]))
        ax.plot([r["ms_per_mpix"] for r in pts], [r["value"] for r in pts], marker=markers[k % len(markers)],
                ms=5, lw=1, label=method)
    front = pareto([(r["ms_per_mpix"], r["value"]) for r in sel])
    if front:
        xs, ys = zip(*front)
        ax.step(xs, ys, where="post", color="black", lw=2, alpha=0.35, label="Pareto front")
        ax.scatter(xs, ys, s=90, facecolors="none", edgecolors="black", lw=1.2, zorder=5)
    ax.set_xscale("log")
    if all(r["value"] > 0 for r in sel):
        ax.set_yscale("log")
    ax.set_xlabel("time per megapixel (ms, log)")
    ax.set_ylabel(spec["label"])
    ax.set_title(f"{sweep}: {scene}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    path = os.path.join(out_dir, f"chart-{sweep}-{scene}.png")
    save_png(fig, path)
    return path


def default_rows(rows, sweep, method):
    """Rows of `method` at the pass's default setting."""
    mine = [r for r in rows if r["sweep"] == sweep and r["method"] == method]
    want = DEFAULT_SETTINGS.get((sweep, method))
    if want is not None:
        hit = [r for r in mine if r["setting"] == want]
        if hit or want == "":
            return hit if hit else mine
    qualities = sorted({r["quality"] for r in mine if math.isfinite(r["quality"])})
    if not qualities:
        return mine
    q = qualities[len(qualities) // 2]
    return [r for r in mine if r["quality"] == q]


def knob_families(rows, sweep):
    fam = defaultdict(set)
    for r in rows:
        if r["sweep"] == sweep and r["knob"]:
            fam[r["family"]].add(r["knob_value"])
    return {f: sorted(v) for f, v in fam.items() if len(v) > 1}


def methods_of(rows, sweep):
    return sorted({r["method"] for r in rows if r["sweep"] == sweep and r["method"] not in ("reference",)
                   and not r["method"].startswith("capture")})


def knob_chart(rows, sweep, family, out_dir):
    spec = SWEEPS[sweep]
    fig, ax = plt.subplots(figsize=(6.4, 3.8), dpi=80)
    knob = ""
    drawn = False
    for method in methods_of(rows, sweep):
        sel = [r for r in default_rows(rows, sweep, method) if r["family"] == family and r["region"] == "all"
               and r["metric"] == spec["metric"] and math.isfinite(r["value"])]
        if len(sel) < 2:
            continue
        sel.sort(key=lambda r: r["knob_value"])
        knob = sel[0]["knob"]
        label = method + (f" ({sel[0]['setting']})" if sel[0]["setting"] else "")
        ax.plot([r["knob_value"] for r in sel], [r["value"] for r in sel], marker="o", ms=4, label=label)
        drawn = True
    if not drawn:
        plt.close(fig)
        return None
    ax.axhline(spec["threshold"], color="red", ls="--", lw=1, label=f"threshold {spec['threshold']:g}")
    ax.set_xlabel(knob)
    ax.set_ylabel(spec["label"])
    ax.set_title(f"{sweep}: {family} across its knob")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(out_dir, f"knob-{sweep}-{family}.png")
    save_png(fig, path)
    return path


def slug(method):
    return re.sub(r"[^a-z0-9]+", "-", method.lower()).strip("-")


def picture_for(pictures, sweep, family, scenes, method, all_methods):
    """The sweep's failure picture for this family: one of the failing scenes,
    preferring the one named after the method."""
    candidates = [p for p in pictures if any(p.startswith(f"{sweep}-{s}") for s in scenes)
                  or p == f"{sweep}-{family}.png"]
    named = [p for p in candidates if p[:-4].endswith("-" + slug(method))]
    if named:
        return named[0]
    # Pictures of one method per scene (fxaa, dof) carry no method name.
    unnamed = [p for p in candidates if not any(p[:-4].endswith("-" + slug(m)) for m in all_methods)]
    return unnamed[0] if unnamed else None


def label_of(method, setting):
    return method + (f" ({setting})" if setting and setting != "default" else "")


def failure_table(rows, sweep, image_dir, doc_dir):
    rule = FAILURE_RULES[sweep]
    pictures = sorted(os.listdir(image_dir)) if os.path.isdir(image_dir) else []
    all_methods = {r["method"] for r in rows if r["sweep"] == sweep}
    lines = [f"Fails when: {rule['rule']}.", "",
             "| method (default setting) | family | knob | holds at | fails at | error where it fails (worst) | picture |",
             "|---|---|---|---|---|---|---|"]
    shown = []
    families = defaultdict(dict)
    for r in rows:
        if r["sweep"] == sweep and r["family"]:
            families[r["family"]][r["scene"]] = (r["knob_value"], r["knob"])
    judged = []  # (method, its rows at the setting judged)
    for method in rule["methods"]:
        if "settings" in rule:  # every listed setting, not only the default
            judged += [(method, [r for r in rows if r["sweep"] == sweep and r["method"] == method
                                 and r["setting"] == setting]) for setting in rule["settings"]]
        else:
            judged.append((method, default_rows(rows, sweep, method)))
    for method, own_rows in judged:
        if not own_rows:
            continue
        base_rows = default_rows(rows, sweep, rule["baseline"]) if "baseline" in rule else []
        floor_rows = default_rows(rows, sweep, rule["floor"]) if "floor" in rule else []
        setting = own_rows[0]["setting"]
        holding = []
        for family in sorted(families):
            scenes = sorted(families[family].items(), key=lambda kv: kv[1][0])
            good, bad = [], []
            for scene, (knob_value, knob) in scenes:
                own = [r for r in own_rows if r["scene"] == scene]
                if not own:
                    continue
                base = [r for r in base_rows if r["scene"] == scene]
                floor = [r for r in floor_rows if r["scene"] == scene]
                label = f"{knob_value:g}" if knob else scene
                failed = rule["judge"](own, base, floor)
                (bad if failed else good).append((label, scene, rule["quote"](own, base, floor)))
            if not bad:
                if good:
                    holding.append(family)
                continue
            knob = scenes[0][1][1] or "–"
            holds = ", ".join(g[0] for g in good) or "–"
            fails = ", ".join(b[0] for b in bad)
            quoted = "; ".join(f"{b[0]}: {b[2]}" for b in bad[:3]) + (" …" if len(bad) > 3 else "")
            pic = picture_for(pictures, sweep, family, [b[1] for b in bad], method, all_methods)
            link = ""
            if pic:
                link = f"[{pic[:-4]}]({os.path.relpath(os.path.join(image_dir, pic), doc_dir)})"
                if pic not in shown:
                    shown.append(pic)
            lines.append(f"| {label_of(method, setting)} | {family} | {knob} | {holds} | **{fails}** | {quoted} | {link} |")
        if holding:
            lines.append(f"| {label_of(method, setting)} | {', '.join(holding)} | | everywhere | – | – | |")
    if shown:
        lines += ["", f"The failures (panels: {rule['panels']}):", ""]
        for p in shown:
            lines += [f"*{p[:-4]}*", "", f"![{p}]({os.path.relpath(os.path.join(image_dir, p), doc_dir)})", ""]
    return "\n".join(lines)


def summary_table(rows, sweep):
    """Per scene: each method's most accurate point and its cost, and which
    methods are on the Pareto front."""
    spec = SWEEPS[sweep]
    sel = [r for r in timed(rows) if r["sweep"] == sweep and r["region"] == "all" and r["metric"] == spec["metric"]
           and math.isfinite(r["value"])]
    scenes = sorted({r["scene"] for r in sel})
    methods = sorted({r["method"] for r in sel})
    head = "| scene | " + " | ".join(methods) + " |"
    lines = [head, "|" + "---|" * (len(methods) + 1)]
    for s in scenes:
        here = [r for r in sel if r["scene"] == s]
        front = set(pareto([(r["ms_per_mpix"], r["value"]) for r in here]))
        cells = []
        for m in methods:
            pts = [r for r in here if r["method"] == m]
            if not pts:
                cells.append("")
                continue
            best = min(pts, key=lambda r: (r["value"], r["ms_per_mpix"]))
            on = any((r["ms_per_mpix"], r["value"]) in front for r in pts)
            cells.append(f"{best['value']:.3g} @ {best['ms_per_mpix']:.3g} ms" + (" ★" if on else ""))
        lines.append(f"| {s} | " + " | ".join(cells) + " |")
    lines.append("")
    lines.append(f"Each cell: the method's lowest {spec['label']} over its settings, and that setting's time per "
                 "megapixel; ★ = at least one of its settings is on the scene's Pareto front.")
    return "\n".join(lines)


def region_table(rows, sweep, metrics):
    """Edge vs interior split at each method's default setting."""
    lines = ["| scene | method | setting | " + " | ".join(f"{m} all / edge / interior" for m in metrics) + " |",
             "|---|---|---|" + "---|" * len(metrics)]
    for scene in sorted({r["scene"] for r in rows if r["sweep"] == sweep}):
        for method in methods_of(rows, sweep):
            sel = [r for r in default_rows(rows, sweep, method) if r["scene"] == scene]
            if not sel:
                continue
            cells = []
            for m in metrics:
                vals = {r["region"]: r["value"] for r in sel if r["metric"] == m}
                cells.append(" / ".join(f"{vals[g]:.3g}" if g in vals and math.isfinite(vals[g]) else "–"
                                        for g in ("all", "edge", "interior")))
            if any(c.replace("–", "").replace(" / ", "") for c in cells):
                lines.append(f"| {scene} | {method} | {sel[0]['setting']} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def contact_sheet(rows, image_dir, out_dir):
    """One picture of every family (its middle knob value) with its name."""
    import matplotlib.image as mpimg
    scenes = defaultdict(list)
    for r in rows:
        if r["sweep"] == "scenes" and r["metric"] == "coverage":
            scenes[r["family"]].append((r["knob_value"], r["scene"], r["value"]))
    picks = []
    for family in sorted(scenes, key=lambda f: min(n for _, n, _ in scenes[f])):
        items = sorted(scenes[family])
        picks.append(items[len(items) // 2])
    picks = [p for p in picks if os.path.exists(os.path.join(image_dir, f"scene-{p[1]}.png"))]
    if not picks:
        return None
    cols = 4
    rows_n = (len(picks) + cols - 1) // cols
    fig, axes = plt.subplots(rows_n, cols, figsize=(cols * 2.2, rows_n * 2.4), dpi=80)
    for ax in axes.flat:
        ax.axis("off")
    for ax, (_, name, coverage) in zip(axes.flat, picks):
        ax.imshow(mpimg.imread(os.path.join(image_dir, f"scene-{name}.png")))
        ax.set_title(f"{name}\n{coverage:.0%} covered", fontsize=8)
    fig.tight_layout()
    path = os.path.join(out_dir, "scenes.png")
    save_png(fig, path)
    return path


def chart_list(paths, doc_dir, width=None):
    """Markdown images, or HTML ones at `width` (e.g. "49%") so that GitHub lays
    several side by side."""
    if width is None:
        return "\n\n".join(f"![{os.path.basename(p)}]({os.path.relpath(p, doc_dir)})" for p in paths if p)
    return "\n".join(f'<img src="{os.path.relpath(p, doc_dir)}" alt="{os.path.basename(p)}" width="{width}">'
                     for p in paths if p)


THIN_FAMILIES = ("particles", "streamlines")
THIN_TARGET = 0.05
# Scenes the ao sweep adds beyond the families' own knob values: PointListAO's
# failure rows (sweep_ao.cpp), counted apart from the issue's eleven.
THIN_EXTRA = ("streamlines-w8", "streamlines-w16")


def beats_ray_tracing(rows):
    """Issue 31's scoreboard: per particle and streamline scene of the ao sweep,
    the fastest image-space or point-list setting with RMSE <= THIN_TARGET that
    every ray-traced setting at no more time per megapixel is worse than."""
    sel = [r for r in timed(rows) if r["sweep"] == "ao" and r["family"] in THIN_FAMILIES and r["region"] == "all"
           and r["metric"] == "rmse" and math.isfinite(r["value"])]
    scenes = sorted({r["scene"] for r in sel}, key=lambda s: (s.split("-")[0], number(re.sub(r"^\D+", "", s.split("-")[-1]))))
    if not scenes:
        return ""
    lines = ["| scene | fastest setting that beats ray tracing | its RMSE @ time | best ray-traced at no more time | "
             "horizon 4 × 8 (default) | point list |", "|---|---|---|---|---|---|"]
    met = extra_met = 0
    for scene in scenes:
        mine = [r for r in sel if r["scene"] == scene]
        traced = [r for r in mine if r["method"].startswith("ray traced")]
        winners = []
        for r in mine:
            if r["method"].startswith("ray traced") or r["value"] > THIN_TARGET:
                continue
            rivals = [t for t in traced if t["ms_per_mpix"] <= r["ms_per_mpix"]]
            if all(t["value"] > r["value"] for t in rivals):
                best_rival = min(rivals, key=lambda t: t["value"]) if rivals else None
                winners.append((r["ms_per_mpix"], r, best_rival))
        horizon = [r for r in mine if r["method"] == "horizon" and r["setting"] == "slices=4 steps=8"]
        hcell = f"{horizon[0]['value']:.3g} @ {horizon[0]['ms_per_mpix']:.3g} ms" if horizon else "–"
        listed = [r for r in mine if r["method"] == "point list"]
        hcell += " | " + (f"{listed[0]['value']:.3g} @ {listed[0]['ms_per_mpix']:.3g} ms" if listed else "–")
        if winners:
            if scene in THIN_EXTRA:
                extra_met += 1
            else:
                met += 1
            _, w, rival = min(winners, key=lambda x: x[0])
            rcell = f"{rival['setting']}: {rival['value']:.3g} @ {rival['ms_per_mpix']:.3g} ms" if rival else "none as fast"
            lines.append(f"| {scene} | {w['method']} ({w['setting']}) | {w['value']:.3g} @ {w['ms_per_mpix']:.3g} ms | "
                         f"{rcell} | {hcell} |")
        else:
            lines.append(f"| {scene} | **none** | – | – | {hcell} |")
    lines.append("")
    extra = [sc for sc in scenes if sc in THIN_EXTRA]
    lines.append(f"**{met} of {len(scenes) - len(extra)}** particle and streamline scenes of the families' sweeps "
                 f"have a method with RMSE ≤ {THIN_TARGET:g} that every ray-traced setting at no more time per "
                 "megapixel is worse than" + (f"; of the {len(extra)} wider line scenes added as PointListAO's "
                 f"failure rows, {extra_met}." if extra else "."))
    return "\n".join(lines)


def layers_table(rows):
    """Issue 30's table: per transparency scene, its depth complexity, and for
    each K the RGB error, the capture's cost against K = 1 and the EXR bytes."""
    sel = [r for r in rows if r["sweep"] == "transparency" and r["region"] == "all"]
    scenes = []
    for r in sel:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    if not scenes:
        return ""
    ks = sorted({int(r["quality"]) for r in sel if r["method"] == "layers + ColorMapping"})

    def value(scene, k, metric, region="all"):
        for r in rows:
            if (r["sweep"] == "transparency" and r["scene"] == scene and r["region"] == region
                    and r["metric"] == metric and (k is None or int(r["quality"]) == k)):
                return r["value"]
        return math.nan

    head = "| scene | crossings (max) | " + " | ".join(f"K = {k}: RMSE / capture × / bytes per px" for k in ks) + " |"
    lines = [head, "|---|---|" + "---|" * len(ks)]
    for scene in scenes:
        one = value(scene, ks[0], "capture_ms_per_mpix")
        cells = []
        for k in ks:
            e, beyond = value(scene, k, "rmse"), value(scene, k, "rmse", "beyond K")
            cost, size = value(scene, k, "capture_ms_per_mpix") / one, value(scene, k, "bytes_per_pixel")
            mark = "**" if e > SWEEPS["transparency"]["threshold"] else ""
            cells.append(f"{mark}{e:.3g}{mark} / {cost:.2g}× / {size:.3g}")
        lines.append(f"| {scene} | {value(scene, None, 'max_crossings'):.0f} | " + " | ".join(cells) + " |")
    lines += ["", "RMSE over covered pixels of the RGB picture (bold: above 0.02); capture × = the K-layer "
              "capture's time over the one-layer capture's of the same scene (issue 30 asks ≤ 1.5 K); bytes per "
              "pixel of the G-buffer as a zip EXR (Z, the colour field and objectId per layer)."]
    return "\n".join(lines)


def layers_storage_table(rows):
    """The storage table's layers rows: bytes per pixel of a layered G-buffer
    (zip EXR) against K, and against K = 1."""
    sel = [r for r in rows if r["sweep"] == "transparency" and r["metric"] == "bytes_per_pixel"]
    if not sel:
        return ""
    ks = sorted({int(r["quality"]) for r in sel})
    scenes = []
    for r in sel:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    lines = ["| scene (Z, colour field, objectId per layer) | " + " | ".join(f"K = {k}" for k in ks) + " |",
             "|---|" + "---|" * len(ks)]
    for scene in scenes:
        by_k = {int(r["quality"]): r["value"] for r in sel if r["scene"] == scene}
        one = by_k.get(ks[0], math.nan)
        lines.append(f"| {scene} | " + " | ".join(f"{by_k[k]:.3g} B ({by_k[k] / one:.2g}×)" for k in ks) + " |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", required=True, help="folder with bench_accuracy's CSV files")
    ap.add_argument("--images", required=True, help="folder for charts (failure pictures are read from here)")
    ap.add_argument("--template", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    rows = load(a.data)
    if not rows:
        sys.exit(f"report.py: no CSV rows in {a.data}")
    os.makedirs(a.images, exist_ok=True)
    shrink_pictures(a.images)
    doc_dir = os.path.dirname(os.path.abspath(a.out))
    blocks = {}
    for sweep in SWEEPS:
        scenes = sorted({r["scene"] for r in rows if r["sweep"] == sweep})
        charts = [speed_error_chart(rows, sweep, s, a.images) for s in scenes]
        blocks[f"charts:{sweep}"] = chart_list(charts, doc_dir, width="49%")
        knobs = [knob_chart(rows, sweep, f, a.images) for f in sorted(knob_families(rows, sweep))]
        blocks[f"knob-charts:{sweep}"] = chart_list(knobs, doc_dir)
        blocks[f"summary:{sweep}"] = summary_table(rows, sweep)
        blocks[f"failures:{sweep}"] = failure_table(rows, sweep, a.images, doc_dir)
    blocks["scenes"] = chart_list([contact_sheet(rows, a.images, a.images)], doc_dir)
    blocks["regions:ao"] = region_table(rows, "ao", ["rmse", "bias"])
    blocks["thin:ao"] = beats_ray_tracing(rows)
    blocks["layers:transparency"] = layers_table(rows)
    blocks["layers-storage:transparency"] = layers_storage_table(rows)
    blocks["regions:normals"] = region_table(rows, "normals", ["angle_median", "angle_p95", "share_above_5"])
    blocks["regions:fxaa"] = region_table(rows, "fxaa", ["rmse"])
    blocks["regions:dof"] = region_table(rows, "dof", ["rmse"])
    storage_csv = os.path.join(a.data, "storage.csv")
    if os.path.exists(storage_csv):
        import storage_table
        blocks["storage"] = storage_table.table(storage_csv)

    out = []
    with open(a.template) as f:
        for line in f:
            m = re.match(r"\s*<!-- generated: (\S+) -->\s*$", line)
            if m:
                out.append(blocks.get(m.group(1), f"*(no data for {m.group(1)} in this run)*") + "\n")
            else:
                out.append(line)
    tmp = a.out + ".tmp"
    with open(tmp, "w") as f:
        f.writelines(out)
    os.replace(tmp, a.out)
    print(f"report.py: wrote {a.out} and {sum(1 for b in blocks.values() if b)} blocks", file=sys.stderr)


if __name__ == "__main__":
    main()
