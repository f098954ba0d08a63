#!/usr/bin/env bash
# Issue 27's refactoring guard with one build: every capture scene and every
# example pipeline of docs/examples (run as scripts/run-examples.sh runs them)
# writes the same bits as recorded in a manifest. It pins today's output; it
# says nothing about whether that output is right (docs/architecture.md).
#   check_example_outputs.sh check  BUILD MANIFEST [WORK_DIR]   (ctest examples_outputs_unchanged)
#   check_example_outputs.sh record BUILD MANIFEST [WORK_DIR]   (after a change meant to change outputs)
# BUILD holds bin/darkroom and lib/darkroom/plugins (a build or install tree).
# MANIFEST has one line per file the run writes, "<path in the output folder>
# <sha256 of its normalised form>", sorted. check names each missing, extra or
# differing file and exits 1 if there is any, 0 if none; 77 (skipped) only
# when the examples read ../shared/data and it is absent. WORK_DIR, if given,
# keeps the outputs for a look; otherwise a temporary folder is removed.
set -euo pipefail
mode=${1:-} build=${2:-} manifest=${3:-}
if [ "$mode" != check ] && [ "$mode" != record ] || [ -z "$build" ] || [ -z "$manifest" ]; then
  echo "usage: $0 check|record DARKROOM_BUILD MANIFEST [WORK_DIR]" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "$build" && pwd)
manifest=$(cd "$(dirname "$manifest")" && pwd)/$(basename "$manifest")

# The TTK pipelines read the shared data beside the checkout; without it they
# cannot run, which is no reason to fail a checkout that lacks it.
if grep -rqsE --include='*.yaml' '^[^#]*shared/data/' "$root/docs/examples" && [ ! -d "$root/../shared/data" ]; then
  echo "$root/../shared/data is absent and docs/examples/ttk reads it: the examples cannot all run here"
  [ "$mode" = check ] && exit 77
  exit 1  # a manifest recorded without them would drop their outputs
fi
command -v python3 > /dev/null || { echo "python3 is needed (scripts/install-deps.sh installs it)"; exit 1; }

if [ -n "${4:-}" ]; then
  work=$4; rm -rf "$work/run"; mkdir -p "$work"
else
  work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fi
work=$(cd "$work" && pwd)
start=$SECONDS
python3 "$root/docs/examples/volume/make_tetrahedra.py" "$work/blobs.vtu"
source "$root/scripts/run-examples.sh"
# Only the build's own plugins: one from elsewhere could change an output.
export DARKROOM_PLUGIN_PATH=
run_all "$root" "$build" "$work/run" "$work/blobs.vtu" > "$work/run.log" 2>&1 || true

# The manifest of what this run wrote. Every file is hashed byte for byte
# (images and the movie too: on one machine their bytes are the same from run
# to run, folder to folder and hour to hour; tried), except for two rules that
# make it independent of where the checkout and the output folder are and of
# file times, and touch nothing else:
#  1. The run's folder and the shared data folder, as named and as resolved,
#     become <out> and <shared> wherever they occur, so a file that names a
#     file it was made from is the same from any folder. (None does today:
#     databases keep relative names.)
#  2. In a database marker (.darkroom-database), the value of the origin line
#     "name, size and time" -- the files a scene reads, hashed with their
#     absolute names and modification times, for --resume -- keeps its count
#     of files and loses the hash. Only the tetrahedra capture has that line.
python3 - "$work/run" "$work/run/shared" > "$work/now.sha256" << 'PY'
import hashlib, os, re, sys

out, shared = sys.argv[1], sys.argv[2]
names = {os.path.realpath(shared): b"<shared>", shared: b"<shared>",
         os.path.realpath(out): b"<out>", out: b"<out>"}
tokens = sorted(((p.encode(), t) for p, t in names.items()), key=lambda pt: -len(pt[0]))
stamp = re.compile(rb"^(origin\t[^\t\n]*\tname, size and time\t\d+ files?) [0-9a-f]+(?=\t|$)", re.M)
lines = []
for folder, dirs, files in os.walk(out):
    if folder == out:  # the examples' copy and the link to the shared data are inputs
        dirs[:] = [d for d in dirs if d not in ("tree", "shared")]
    for name in files:
        path = os.path.join(folder, name)
        rel = os.path.relpath(path, out)
        if any(c.isspace() for c in rel):
            sys.exit(f"a file name with white space cannot go into the manifest: {rel!r}")
        with open(path, "rb") as f:
            data = f.read()
        for p, t in tokens:
            data = data.replace(p, t)
        if name == ".darkroom-database":
            data = stamp.sub(rb"\1 <name,size,time>", data)
        lines.append(f"{rel} {hashlib.sha256(data).hexdigest()}")
print("\n".join(sorted(lines)))
PY
files=$(wc -l < "$work/now.sha256")
failed=$(grep '^FAILED' "$work/run.log" || true)

if [ "$mode" = record ]; then
  if [ -n "$failed" ]; then
    echo "not recorded: some examples failed"; echo "$failed"; cat "$work/run.log"; exit 1
  fi
  cp "$work/now.sha256" "$manifest"
  echo "recorded $files files into $manifest with $build ($((SECONDS - start)) s)"
  exit 0
fi

# One line per path: the recorded hash, this run's; "-" where one lacks it
# (sorted again, so that a hand-edited manifest still joins).
export LC_ALL=C
diffs=$(join -a1 -a2 -e - -o 0,1.2,2.2 <(sort "$manifest") <(sort "$work/now.sha256") | awk '
  $2 == "-" { print "extra (not in the manifest): " $1; next }
  $3 == "-" { print "missing (recorded, not written): " $1; next }
  $2 != $3  { print "differs: " $1 }')
if [ -z "$diffs" ] && [ -z "$failed" ]; then
  echo "all $files files as recorded in $manifest ($((SECONDS - start)) s)"
  exit 0
fi
echo "$diffs"
[ -z "$failed" ] || echo "$failed"
echo "--- what darkroom printed:"; cat "$work/run.log"
# A capture database among the differences: Embree chooses its kernels from
# the CPU at run time (AVX-512, AVX2, SSE/AVX give different last bits), so
# a manifest recorded on another class of CPU differs from a capture here.
if grep -q '^differs: .*\.cdb/[^/]*\.exr$' <<< "$diffs"; then
  flags=$(grep -m1 '^flags' /proc/cpuinfo || true)
  class="SSE/AVX"
  [[ " $flags " == *" avx2 "* && " $flags " == *" fma "* ]] && class=AVX2
  [[ " $flags " == *" avx512f "* && " $flags " == *" avx512vl "* && " $flags " == *" avx512bw "* ]] && class=AVX-512
  echo "note: captured G-buffers differ; this CPU runs Embree's $class kernels, and the manifest" \
       "must come from the same class (docs/architecture.md, 'The examples' outputs')"
fi
# The movie: x264 runs 1.5 threads per CPU the process may use (it writes
# "threads=N" into the file), and its encoding depends on that number.
if grep -q '^differs: .*\.mp4$' <<< "$diffs"; then
  echo "note: the movie differs; x264 encoded it with threads=$(( $(nproc) * 3 / 2 )) here, and the manifest" \
       "holds for the count it was recorded with (docs/architecture.md, 'The examples' outputs')"
fi
exit 1
