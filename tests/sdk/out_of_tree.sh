#!/usr/bin/env bash
# The plugin author's path, end to end: install the SDK, build the example
# plugins out of tree with find_package(Darkroom), load them with the runner:
# invert (the SDK alone) and cinema-first (the data library, Darkroom::data,
# reading a Cinema database).
set -euo pipefail
: "${DARKROOM_BINARY_DIR:?}" "${DARKROOM_SOURCE_DIR:?}"
cmake=${CMAKE_COMMAND:-cmake}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "== install into a fresh prefix"
"$cmake" --install "$DARKROOM_BINARY_DIR" --prefix "$work/prefix" > "$work/install.log"
test -f "$work/prefix/lib/cmake/Darkroom/DarkroomConfig.cmake"

for variant in installed buildtree; do
  if [ $variant = installed ]; then dir="$work/prefix/lib/cmake/Darkroom"; else dir="$DARKROOM_BINARY_DIR"; fi
  for example in invert cinema-first; do
    echo "== build the $example example against the $variant SDK"
    "$cmake" -S "$DARKROOM_SOURCE_DIR/sdk/examples/$example" -B "$work/build-$example-$variant" -G Ninja \
      -DDarkroom_DIR="$dir" -DCMAKE_BUILD_TYPE=Release > "$work/configure-$example-$variant.log"
    "$cmake" --build "$work/build-$example-$variant" > "$work/build-$example-$variant.log"
    test -f "$work/build-$example-$variant/darkroom-$example.so"
  done
done

runner="$work/prefix/bin/darkroom"
plugin="$work/build-invert-installed/darkroom-invert.so"
echo "== the installed runner lists and describes the plugin"
"$runner" --plugin-path "$plugin" plugins | tee "$work/plugins.txt"
grep -q "Invert" "$work/plugins.txt"
grep -q "invert-example" "$work/plugins.txt"
DARKROOM_PLUGIN_PATH="$work/build-invert-installed" "$runner" describe Invert | tee "$work/describe.txt"
grep -q "amount" "$work/describe.txt"

echo "== run a pipeline through the plugin"
oiiotool --pattern constant:color=0.2,0.4,0.6,1 8x8 4 -d float -o "$work/in.exr"
cat > "$work/invert.yaml" <<YAML
darkroom: 1
nodes:
  read:
    type: ImageReader
    parameters:
      path: in.exr
  invert:
    type: Invert
  write:
    type: ImageWriter
    parameters:
      path: out.exr
edges:
  - read.image -> invert.image
  - invert.image -> write.image
YAML
"$runner" --plugin-path "$plugin" run "$work/invert.yaml"
stats=$(oiiotool "$work/out.exr" --printstats)
echo "$stats" | grep -E "Avg:" 
echo "$stats" | grep -qE "Avg: 0\.80+ 0\.60+ 0\.40+ 1\.0+" || { echo "unexpected pixel values"; exit 1; }

echo "== a plugin reading a Cinema database through the installed data library"
mkdir -p "$work/db.cdb"
oiiotool --pattern constant:color=0.25,0.5,0.75,1 6x4 4 -d float -o "$work/db.cdb/time=1.exr"
oiiotool --pattern constant:color=0.9,0.9,0.9,1 6x4 4 -d float -o "$work/db.cdb/time=2.exr"
printf 'time,FILE\n1,time=1.exr\n2,time=2.exr\n' > "$work/db.cdb/data.csv"
cat > "$work/first.yaml" <<YAML
darkroom: 1
nodes:
  first:
    type: CinemaFirst
    parameters:
      database: db.cdb
  write:
    type: ImageWriter
    parameters:
      path: first.exr
edges:
  - first.image -> write.image
YAML
"$runner" --plugin-path "$work/build-cinema-first-installed/darkroom-cinema-first.so" run "$work/first.yaml"
stats=$(oiiotool "$work/first.exr" --printstats)
echo "$stats" | grep -E "Avg:"
echo "$stats" | grep -qE "Avg: 0\.250* 0\.50* 0\.750* 1\.0+" || { echo "unexpected pixel values"; exit 1; }
echo "out-of-tree plugins: OK"
