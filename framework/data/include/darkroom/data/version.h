#pragma once
// The data library's ABI version: out-of-tree plugins that read Cinema
// databases link libdarkroom-data (find_package(Darkroom), Darkroom::data),
// so its exported interface is checked against a committed baseline like
// the SDK's (framework/data/abi, tests/sdk/check_abi.sh ... data). Bump it on
// an incompatible change and record the new baseline with
// scripts/update-abi.sh data; the library's soname carries the project's
// major.minor version, so a plugin built against another cannot load it.
#define DARKROOM_DATA_ABI_VERSION 2
