#!/usr/bin/env python3
"""Markdown tables of the "storage" accuracy sweep (bench/accuracy/sweep_storage.cpp).

    python3 bench/accuracy/storage_table.py OUT/storage.csv

    python3 bench/accuracy/storage_table.py --cinema build/bin/darkroom \\
        docs/examples/demo/surface.yaml OUT/storage.csv

The first prints, per scene: bytes per entry of each stored channel under each OpenEXR
compression (float32 and half), the accuracy of stored against reconstructed
normals, what half scalars lose, and write/read times; the second appends what `darkroom capture` stores per
Cinema entry under each --compression / --half option. table(csv_path) returns
the same text, for docs/accuracy-storage.md.
"""
import csv
import math
import os
import subprocess
import sys
import tempfile
from collections import OrderedDict

VARIANTS = ["none", "zip", "piz", "zip half", "piz half"]
VARIANT_TITLES = ["none", "ZIP", "PIZ", "ZIP half", "PIZ half"]


def _load(csv_path):
    """{scene: {(method, setting, region, metric): (value, ms_per_mpix)}} in file order."""
    scenes = OrderedDict()
    with open(csv_path, newline="") as f:
        for r in csv.DictReader(f):
            if r["sweep"] != "storage":
                continue
            key = (r["method"], r["setting"], r["region"], r["metric"])
            scenes.setdefault(r["scene"], {})[key] = (float(r["value"]), float(r["ms_per_mpix"]))
    return scenes


def _kib(v):
    if v is None or math.isnan(v):
        return "–"
    return f"{v / 1024:,.0f}" if v >= 10 * 1024 else f"{v / 1024:,.1f}"


def _num(v, digits=2):
    if v is None or math.isnan(v):
        return "–"
    return f"{v:.{digits}f}"


def _get(d, method, setting, metric, region="all"):
    hit = d.get((method, setting, region, metric))
    return None if hit is None else hit[0]


def _ms(d, method, setting, metric, region="all"):
    hit = d.get((method, setting, region, metric))
    return None if hit is None else hit[1]


def _pixels(d):
    """Image pixels, from a file's bytes and bytes per pixel."""
    b = _get(d, "zip", "Z", "bytes")
    bpp = _get(d, "zip", "Z", "bytes_per_pixel")
    return round(b / bpp) if b and bpp else None


def bytes_table(d):
    """Rows: channels; columns: compressions; cells: KiB per entry."""
    rows = [("Z", "Z (float32; kept float32 by --half)", None),
            ("Z", "Z as half (not written by darkroom)", "{} (Z as half)"),
            ("scalar", "scalar (the colour field)", None),
            ("N", "N.x N.y N.z", None),
            ("objectId", "objectId (uint32)", None),
            ("entry", "**whole entry** (all four in one file)", None),
            ("header", "header only (1×1 file)", None)]
    out = ["| channel | " + " | ".join(VARIANT_TITLES) + " |",
           "|---|" + "---:|" * len(VARIANTS)]
    for setting, title, method_fmt in rows:
        cells = []
        for v in VARIANTS:
            method = method_fmt.format(v) if method_fmt else v
            val = _get(d, method, setting, "bytes")
            if method_fmt and not v.endswith("half"):
                val = None
            cells.append(_kib(val))
        if all(c == "–" for c in cells):
            continue
        out.append(f"| {title} | " + " | ".join(cells) + " |")
    return "\n".join(out)


NORMAL_ROWS = [
    # (label, method, setting, bytes: (method, setting) of the stored channel or None)
    ("stored N float32 (ZIP)", "N float32", "zip", ("zip", "N")),
    ("stored N half (ZIP half)", "N half", "zip half", ("zip half", "N")),
    ("reconstructed, central", "central", "captured", None),
    ("reconstructed, extrapolated", "extrapolated", "captured", None),
    ("central from Z stored as half", "central", "zip half (Z as half)", None),
    ("extrapolated from Z stored as half", "extrapolated", "zip half (Z as half)", None),
]


def normals_table(d):
    """Stored against reconstructed normals: extra bytes, angular error by region."""
    out = ["| normals | extra KiB per entry | median / p95 all (°) | median / p95 interior (°) | "
           "median / p95 edge (°) | > 5° (all) | reconstruction ms/Mpix |",
           "|---|---:|---:|---:|---:|---:|---:|"]
    for label, method, setting, stored in NORMAL_ROWS:
        if _get(d, method, setting, "angle_median") is None:
            continue
        extra = _get(d, stored[0], stored[1], "bytes") if stored else 0.0
        cells = [_kib(extra)]
        for region in ("all", "interior", "edge"):
            cells.append(f"{_num(_get(d, method, setting, 'angle_median', region))} / "
                         f"{_num(_get(d, method, setting, 'angle_p95', region))}")
        share = _get(d, method, setting, "share_above_5")
        cells.append("–" if share is None else f"{100 * share:.1f} %")
        ms = _ms(d, method, setting, "angle_median") if not stored else None
        cells.append(_num(ms, 1) if ms else "–")
        out.append(f"| {label} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def objects_table(d):
    """Scenes of several objects: reconstruction error on each object's pixels."""
    settings = []
    for (method, setting, _, metric) in d:
        if method == "extrapolated" and setting.startswith("captured, ") and metric == "pixels" \
                and setting not in settings:
            settings.append(setting)
    if not settings:
        return ""
    out = ["| reconstructed on | pixels | central median / p95 (°) | extrapolated median / p95 (°) | "
           "> 5° central / extrapolated |", "|---|---:|---:|---:|---:|"]
    for setting in settings:
        name = setting[len("captured, "):-len(" only")]
        cells = [f"{int(_get(d, 'extrapolated', setting, 'pixels')):,}"]
        for method in ("central", "extrapolated"):
            cells.append(f"{_num(_get(d, method, setting, 'angle_median'))} / "
                         f"{_num(_get(d, method, setting, 'angle_p95'))}")
        cells.append(" / ".join(f"{100 * _get(d, m, setting, 'share_above_5'):.0f} %"
                                for m in ("central", "extrapolated")))
        out.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def facts(d):
    """One line: Z read back bit-identical, half scalar error, pixel counts by region."""
    z_same = [_get(d, "Z read back", v, "z_bitwise_equal") for v in VARIANTS]
    z_text = ("Z read back bit-identical under every variant"
              if all(s == 1.0 for s in z_same) else
              "Z read back NOT identical under: " + ", ".join(v for v, s in zip(VARIANTS, z_same) if s != 1.0))
    maxe = _get(d, "zip half", "scalar", "max_error_of_range")
    rmse = _get(d, "zip half", "scalar", "rmse_of_range")
    nanm = _get(d, "zip half", "scalar", "nan_mismatch")
    edge = _get(d, "central", "captured", "pixels", "edge")
    interior = _get(d, "central", "captured", "pixels", "interior")
    parts = [z_text]
    if maxe is not None:
        parts.append(f"half scalar: max error {maxe * 255:.3f} and RMSE {rmse * 255:.4f} of an 8-bit "
                     f"colour-map step (1/255 of the range), {int(nanm)} NaN mismatches")
    if edge is not None:
        parts.append(f"{int(interior):,} interior and {int(edge):,} edge pixels")
    return "; ".join(parts) + "."


def timing_table(d):
    """Write and read time of the whole entry per variant: wall time and CPU
    time of all threads (best of the sweep's repeats)."""
    out = ["| whole entry | " + " | ".join(VARIANT_TITLES) + " |", "|---|" + "---:|" * len(VARIANTS)]
    for metric, title in (("write_ms", "write, wall (ms)"), ("write_cpu_ms", "write, CPU (ms)"),
                          ("read_ms", "read, wall (ms)"), ("read_cpu_ms", "read, CPU (ms)")):
        out.append(f"| {title} | " + " | ".join(_num(_get(d, v, "entry", metric), 1) for v in VARIANTS) + " |")
    return "\n".join(out)


def cinema_table(d):
    """Rows written by --cinema: `darkroom capture` per option, bytes per entry."""
    rows = [(k[1], v[0]) for k, v in d.items() if k[0] == "darkroom capture" and k[3] == "bytes_per_entry"]
    if not rows:
        return ""
    out = ["| `darkroom capture` options | KiB per entry |", "|---|---:|"]
    out += [f"| `{opts}` | {_kib(b)} |" for opts, b in rows]
    return "\n".join(out)


def _bpp_range(values):
    values = [v for v in values if v is not None]
    if not values:
        return "–"
    lo, hi = min(values), max(values)
    return f"{lo:.2f}" if abs(hi - lo) < 0.005 else f"{lo:.2f}–{hi:.2f}"


def summary_bytes(scenes):
    """Bytes per pixel of each channel, lowest–highest over the scenes."""
    rows = [("Z", "Z (float32)"), ("scalar", "scalar"), ("N", "N.x N.y N.z"), ("objectId", "objectId"),
            ("entry", "**whole entry**")]
    out = ["| bytes per pixel | " + " | ".join(VARIANT_TITLES) + " |", "|---|" + "---:|" * len(VARIANTS)]
    for setting, title in rows:
        cells = [_bpp_range([_get(d, v, setting, "bytes_per_pixel") for d in scenes.values()]) for v in VARIANTS]
        out.append(f"| {title} | " + " | ".join(cells) + " |")
    cells = ["–"] * 3 + [_bpp_range([_get(d, f"{v} (Z as half)", "Z", "bytes_per_pixel") for d in scenes.values()])
                         for v in VARIANTS[3:]]
    out.append("| Z as half (not written by darkroom) | " + " | ".join(cells) + " |")
    return "\n".join(out)


def summary_normals(scenes):
    """Per scene: what storing N as half costs against reconstructing it."""
    out = ["| scene | N half (ZIP) bytes/px | N half p95 all (°) | extrapolated median / p95 interior (°) | "
           "extrapolated median / p95 edge (°) | edge pixels | extrapolated > 5° (all) |",
           "|---|---:|---:|---:|---:|---:|---:|"]
    for scene, d in scenes.items():
        if _get(d, "extrapolated", "captured", "angle_median") is None:
            continue
        share = _get(d, "extrapolated", "captured", "share_above_5")
        edge = _get(d, "central", "captured", "pixels", "edge")
        valid = edge + _get(d, "central", "captured", "pixels", "interior")
        out.append(f"| {scene} | {_num(_get(d, 'zip half', 'N', 'bytes_per_pixel'))} | "
                   f"{_num(_get(d, 'N half', 'zip half', 'angle_p95'))} | "
                   f"{_num(_get(d, 'extrapolated', 'captured', 'angle_median', 'interior'))} / "
                   f"{_num(_get(d, 'extrapolated', 'captured', 'angle_p95', 'interior'))} | "
                   f"{_num(_get(d, 'extrapolated', 'captured', 'angle_median', 'edge'))} / "
                   f"{_num(_get(d, 'extrapolated', 'captured', 'angle_p95', 'edge'))} | "
                   f"{100 * edge / valid:.0f} % | {100 * share:.1f} % |")
    return "\n".join(out)


SHIFTS = [(0, "scalar"), (1, "scalar + 1 ranges"), (4, "scalar + 4 ranges"), (16, "scalar + 16 ranges"),
          (64, "scalar + 64 ranges")]


def summary_half(scenes):
    """Largest error of half scalars in 8-bit colour-map steps (1/255 of the
    range), the field as captured and shifted by k ranges."""
    out = ["| scene | " + " | ".join("as captured" if k == 0 else f"+{k} ranges" for k, _ in SHIFTS) + " |",
           "|---|" + "---:|" * len(SHIFTS)]
    for scene, d in scenes.items():
        cells = []
        for _, setting in SHIFTS:
            e = _get(d, "zip half", setting, "max_error_of_range")
            cells.append("–" if e is None else f"{255 * e:.2f}")
        out.append(f"| {scene} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def table(csv_path):
    """Summaries over the scenes, then all tables per scene, as Markdown."""
    scenes = _load(csv_path)
    images = OrderedDict((k, v) for k, v in scenes.items() if k != "cinema")
    parts = []
    if images:
        parts.append("### All scenes\n\nBytes per pixel (entry size = this × pixels), lowest–highest over "
                     f"{', '.join(images)}:\n\n{summary_bytes(images)}\n\n"
                     "Normals: stored as half against reconstructed from Z (`extrapolated`, the Normals "
                     f"default):\n\n{summary_normals(images)}\n\n"
                     "Half scalars: largest error in 8-bit colour-map steps (1/255 of the field's range), the "
                     f"field as captured and shifted by k ranges:\n\n{summary_half(images)}")
    for scene, d in scenes.items():
        if scene == "cinema":
            parts.append("### Cinema database (`darkroom capture`, docs/examples/demo/surface.yaml)\n\n"
                         + cinema_table(d))
            continue
        px = _pixels(d)
        size = f" ({px:,} pixels)" if px else ""
        parts.append(f"### {scene}{size}\n\n"
                     f"KiB per entry:\n\n{bytes_table(d)}\n\n"
                     f"Normals against the captured (exact) ones:\n\n{normals_table(d)}\n\n"
                     + (f"By object:\n\n{objects_table(d)}\n\n" if objects_table(d) else "") +
                     f"{facts(d)}\n\n{timing_table(d)}")
    return "\n\n".join(parts) + "\n"


CINEMA_OPTIONS = [["--compression", "none"], ["--compression", "zip"], ["--compression", "piz"],
                  ["--compression", "zip", "--half"], ["--compression", "piz", "--half"]]


def measure_cinema(darkroom, scene_file, csv_path):
    """Captures scene_file with `darkroom capture` under each option into a
    temporary database and appends its bytes per entry (EXR products and the
    whole folder with data.csv) to csv_path as scene "cinema" rows."""
    with open(csv_path, "a", newline="") as f, tempfile.TemporaryDirectory() as tmp:
        w = csv.writer(f)
        for i, opts in enumerate(CINEMA_OPTIONS):
            db = os.path.join(tmp, f"db{i}.cdb")
            subprocess.run([darkroom, "--quiet", "capture", scene_file, "-o", db] + opts, check=True)
            exr, total, entries = 0, 0, 0
            for root, _, files in os.walk(db):
                for name in files:
                    size = os.path.getsize(os.path.join(root, name))
                    total += size
                    if name.endswith(".exr"):
                        exr += size
                        entries += 1
            for metric, value in (("bytes_per_entry", exr / entries), ("folder_bytes_per_entry", total / entries),
                                  ("entries", entries)):
                w.writerow(["storage", "cinema", "cinema", "", 0, "darkroom capture", " ".join(opts), 0, 0,
                            "all", metric, value])


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "--cinema":
        measure_cinema(sys.argv[2], sys.argv[3], sys.argv[4])
    elif len(sys.argv) == 2:
        sys.stdout.write(table(sys.argv[1]))
    else:
        sys.exit("usage: storage_table.py STORAGE_CSV\n"
                 "       storage_table.py --cinema DARKROOM_BINARY SCENE_FILE STORAGE_CSV  (appends rows)")
