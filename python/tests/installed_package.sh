#!/usr/bin/env bash
# What `cmake --install` makes of the Python package works on its own: the
# package is found on the interpreter's site-packages path below the prefix,
# loads the installed plugins (not the build tree's), shades a picture, and
# writes and reads pycinema's .h5 through the installed HDF5 module (opened
# on first use from beside the installed data library).
#   installed_package.sh BUILD_DIR PYTHON SITE_DIR
# SITE_DIR: the package's install folder below the prefix (lib/python3.X/...).
set -euo pipefail
build=$1 python=$2 site=$3
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > /dev/null
# Nothing of the build tree on the way: another folder, no plugin path.
cd "$prefix"
PYTHONPATH="$prefix/$site" DARKROOM_PLUGIN_PATH= "$python" - "$prefix" << 'PY'
import os, sys
import numpy as np
import darkroom as dr

prefix = sys.argv[1]
assert dr.__file__.startswith(prefix), dr.__file__
assert not dr.plugin_problems, dr.plugin_problems
paths = [p["path"] for p in dr.plugins()]
assert paths and all(p.startswith(prefix) for p in paths), paths
assert "ColorMapping" in dr.node_types()
dr.Image.from_arrays({"value": np.linspace(0, 1, 64, dtype=np.float32).reshape(8, 8)}).save("ramp.exr")
p = dr.Pipeline()
read = p.add("ImageReader", name="read", path=os.path.abspath("ramp.exr"))
colour = p.add("ColorMapping", name="colour", channel="value", colormap="viridis")
p.connect(read.image, colour.image)
rgba = p.evaluate(colour.image).to_rgba8()
assert rgba.shape == (8, 8, 4) and rgba[0, 0, 3] == 255 and (rgba[0, 0] != rgba[-1, -1]).any()
with dr.DatabaseWriter("h5.cdb", ["time"], format="h5") as w:
    w.add({"time": 0.5}, dr.Image.from_arrays({"value": np.full((4, 4), 0.25, dtype=np.float32)}))
assert sorted(os.listdir("h5.cdb")) and any(f.endswith(".h5") for f in os.listdir("h5.cdb")), os.listdir("h5.cdb")
assert dr.Database("h5.cdb").read(where="time=0.5")["value"][0, 0] == 0.25
print("installed package at", os.path.dirname(dr.__file__), "with", len(paths), "plugins: shaded", rgba.shape)
PY
