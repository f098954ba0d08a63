#!/usr/bin/env bash
# Issue 27's refactoring guard with one build: every capture scene and every
# example pipeline of docs/examples (run as scripts/run-examples.sh runs them)
# writes the same bits as recorded in a manifest. It pins today's output; it
# says nothing about whether that output is right (docs/architecture.md).
#   check_example_outputs.sh check  BUILD MANIFEST [WORK_DIR]   (ctest examples_outputs_unchanged)
#   check_example_outputs.sh record BUILD MANIFEST [WORK_DIR]   (after a change meant to change outputs)
# BUILD holds bin/darkroom and lib/darkroom/plugins (a build or install tree).
# MANIFEST has one line per file the run writes, "<path in the output folder>
# <sha256 of its normalised form>", sorted, after a first line naming the
# machine class it was recorded on (below). check names each missing, extra
# or differing file and exits 1 if there is any, 0 if none; 77 (skipped) when
# the examples read ../shared/data and it is absent, or when this machine's
# class differs from the recorded one, saying why. WORK_DIR, if given,
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

# What the bits depend on beyond the code: Embree chooses its kernels from the
# CPU at run time (AVX-512, AVX2 and SSE/AVX give different last bits in the
# captured depth, so nearly every output differs; measured), and x264 runs
# 1.5 threads per CPU the process may use, which changes the movie alone.
embree_class() {
  local flags class="SSE/AVX"
  flags=" $(grep -m1 '^flags' /proc/cpuinfo || true) "
  [[ $flags == *" avx2 "* && $flags == *" fma "* ]] && class=AVX2
  [[ $flags == *" avx512f "* && $flags == *" avx512vl "* && $flags == *" avx512bw "* ]] && class=AVX-512
  echo "$class"
}
here_class=$(embree_class)
here_threads=$(( $(nproc) * 3 / 2 ))

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
  { echo "# recorded with Embree's $here_class kernels; x264 threads=$here_threads"; cat "$work/now.sha256"; } > "$manifest"
  echo "recorded $files files into $manifest with $build ($((SECONDS - start)) s)"
  exit 0
fi

# Another class of CPU gives other last bits everywhere: nothing to compare
# here, said plainly (scripts/compare-outputs.sh compares two builds on any
# machine). Another CPU count changes only the movie, which is then left out.
header=$(head -n1 "$manifest")
recorded_class=$(sed -n "s/^# recorded with Embree's \([^ ]*\) kernels.*/\1/p" <<< "$header")
recorded_threads=$(sed -n 's/.*x264 threads=\([0-9]*\).*/\1/p' <<< "$header")
if [ "$recorded_class" != "$here_class" ]; then
  echo "skipped: $manifest was recorded on a CPU running Embree's ${recorded_class:-unknown} kernels;" \
       "this one runs its $here_class kernels, whose captures differ in the last bits." \
       "Compare two builds here with scripts/compare-outputs.sh OLD NEW, or re-record on this class."
  exit 77
fi
skip_movies=cat
if [ "$recorded_threads" != "$here_threads" ]; then
  echo "note: the movies are left out: x264 encodes with threads=$here_threads here, the manifest" \
       "was recorded with threads=${recorded_threads:-unknown}"
  skip_movies="grep -v \.mp4 "
fi

# One line per path: the recorded hash, this run's; "-" where one lacks it
# (sorted again, so that a hand-edited manifest still joins).
export LC_ALL=C
diffs=$(join -a1 -a2 -e - -o 0,1.2,2.2 <(grep -v '^#' "$manifest" | $skip_movies | sort) \
                                       <($skip_movies < "$work/now.sha256" | sort) | awk '
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
exit 1
