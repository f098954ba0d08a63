# Sourced by tests/sdk/check_abi.sh and scripts/update-abi.sh: where a
# library's public headers, ABI version and baselines are, and the one abidw
# command both use (so a recorded baseline and a check compare alike).
#   source abi_component.sh SOURCE_DIR sdk|data
case "$2" in
  sdk)
    headers="$1/sdk/include/darkroom"
    version_header="$1/sdk/include/darkroom/version.h"
    macro=DARKROOM_ABI_VERSION
    baseline_dir="$1/sdk/abi"
    ;;
  data)
    headers="$1/framework/data/include/darkroom/data"
    version_header="$1/framework/data/include/darkroom/data/version.h"
    macro=DARKROOM_DATA_ABI_VERSION
    baseline_dir="$1/framework/data/abi"
    ;;
  *)
    echo "abi: unknown library '$2' (sdk or data)" >&2
    exit 2
    ;;
esac
version=$(sed -n "s/^#define $macro \([0-9]*\)u\{0,1\}.*/\1/p" "$version_header")
baseline="$baseline_dir/darkroom-$2-abi$version.xml"
# Standard library template instantiations are not compared (why: abi_suppressions.ini).
abi_suppressions="$1/scripts/abi_suppressions.ini"
abi_dump() {
  abidw --headers-dir "$headers" --no-corpus-path --no-show-locs --drop-private-types --no-comp-dir-path \
    --exported-interfaces-only --type-id-style hash --no-elf-needed --out-file "$2" "$1"
}
