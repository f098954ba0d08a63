#pragma once
// `mpirun -np N darkroom capture SCENE -o DB`: each rank loads its part of
// the scene, ray traces it for every camera, the G-buffers are composited by
// depth (binary swap) and rank 0 writes the database (docs/scale-out.md).
#include "cli.h"

#include <string>

namespace darkroom::cli {

struct CaptureSettings {
    std::string scene, output, compression;
    bool overwrite = false, resume = false, half = false;
    int threads = 0;
};

// Built with MPI: runs the capture over MPI_COMM_WORLD. Without MPI it is
// never called (processes().size is 1) and reports an error.
int captureOverRanks(const GlobalOptions& global, const CaptureSettings& settings);

}  // namespace darkroom::cli
