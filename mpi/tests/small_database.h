#pragma once
// The source database the `--foreach` tests over ranks shade: an isosurface
// with a height field from 10 cameras (5 azimuths x 2 elevations), 40 x 32
// pixels, captured by the runner alone into `dir`/db.cdb.
#include "run_process.h"
#include "test_support.h"

namespace darkroom::test {

inline RunResult captureSmallDatabase(const TempDir& dir) {
    writeText(dir.file("scene.yaml"),
              "objects:\n"
              "  - generator: isosurface\n"
              "    parameters: {resolution: 24}\n"
              "    fields: [height]\n"
              "cameras:\n"
              "  resolution: [40, 32]\n"
              "  grid: {phi: 5, theta: [0, 40]}\n"
              "channels:\n"
              "  scalars: [height]\n");
    return runAlone({"capture", dir.file("scene.yaml"), "-o", dir.file("db.cdb"), "-q"});
}

}  // namespace darkroom::test
