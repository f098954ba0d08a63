// A staged data.csv (issue 26, S2): what a run over MPI ranks left in
// <database>.staging/rank-0 is read as input from outside. Whatever the
// file says, only plain files inside the rank's folder are adopted: never a
// link (link.exr points at a file outside), never a path leading elsewhere
// (../secret.txt exists), never a folder.
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/workflows/staging.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

// The staging folder with its marker and rank-0, a few files a data.csv may
// name, and the traps: a file outside and a link to it. Made once.
const fs::path& stagingFolder() {
    static const fs::path folder = [] {
        const fs::path root = fuzz::scratchFolder();
        const fs::path staging = root / "db.cdb.staging", rank = staging / "rank-0";
        fs::create_directories(rank / "sub");
        std::ofstream(staging / darkroom::workflows::kStagingMarker) << "marker\n";
        std::ofstream(root / "secret.txt") << "not Darkroom's\n";
        std::ofstream(staging / "secret.txt") << "not an entry\n";
        for (const char* name : {"a.exr", "b.exr", "a.points.csv", "time=1.exr", "x"}) std::ofstream(rank / name) << "data";
        fs::create_symlink(root / "secret.txt", rank / "link.exr");
        return staging;
    }();
    return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const fs::path& staging = stagingFolder();
    const fs::path rank = staging / "rank-0";
    std::ofstream(rank / "data.csv", std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                             std::streamsize(size));
    try {
        const auto staged = darkroom::workflows::readStagedDatabases(staging.string());
        const auto inside = [&](const std::string& path) {
            const fs::path p(path);
            return p.parent_path() == rank && fs::is_regular_file(fs::symlink_status(p));
        };
        for (const auto& e : staged.entries) {
            fuzz::expect(inside(e.product), "a product adopted is a plain file inside its rank's folder");
            for (const auto& [column, file] : e.attachments)
                fuzz::expect(inside(file), "an attachment adopted is a plain file inside its rank's folder");
        }
    } catch (const darkroom::Error&) {
    }
    return 0;
}
