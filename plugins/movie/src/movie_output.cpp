#include "movie_output.h"

#include <darkroom/context.h>
#include <darkroom/error.h>

#include <cerrno>
#include <csignal>
#include <filesystem>
#include <string_view>
#include <unistd.h>

namespace darkroom::movie {

namespace fs = std::filesystem;

namespace {

// A folder made absolute and resolved through symbolic links as far as it exists.
fs::path realFolder(const fs::path& folder) {
    const fs::path absolute = fs::absolute(folder.empty() ? fs::path(".") : folder).lexically_normal();
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(absolute, ec);
    return ec ? absolute : real;
}

bool allDigits(std::string_view s) {
    return !s.empty() && s.size() <= 10 && s.find_first_not_of("0123456789") == std::string_view::npos;
}

// Whether a process `pid` runs on this machine (one we may not signal runs
// too); numbers no pid can be count as alive, so their files stay.
bool processAlive(long pid) {
    if (pid <= 0 || pid > 0x7fffffffL || pid == long(::getpid())) return true;
    return ::kill(pid_t(pid), 0) == 0 || errno == EPERM;
}

}  // namespace

std::string resolveMoviePath(const Context& ctx, const std::string& given) {
    const std::string target = ctx.resolveOutputPath(given);
    // An output folder of the run's own: outputs do not resolve where inputs do.
    const std::string outputRoot = ctx.resolveOutputPath(".");
    if (outputRoot == ctx.resolveInputPath(".")) return fs::absolute(target).lexically_normal().string();
    // Where the temporary is made and renamed to: the file's folder through
    // its links, so a link inside the output folder cannot lead out of it.
    const fs::path normal = fs::path(target).lexically_normal();
    const fs::path real = realFolder(normal.parent_path()) / normal.filename();
    const fs::path inside = real.lexically_relative(realFolder(outputRoot));
    if (normal.filename().empty() || inside.empty() || inside == "." || *inside.begin() == "..")
        throw InputError("path '" + given + "' is not a file inside the output folder " + outputRoot +
                         " (--output); a movie is written there: give a path relative to it, e.g. movie.mp4");
    return fs::absolute(target).lexically_normal().string();
}

std::string fileUrl(const std::string& path) { return "file:" + fs::absolute(path).string(); }

std::vector<std::string> removeStaleTemporaries(const std::string& target) {
    std::vector<std::string> removed;
    const fs::path t(target);
    const std::string prefix = t.stem().string() + ".tmp-", extension = t.extension().string();
    std::error_code ec;
    fs::directory_iterator it(t.parent_path().empty() ? "." : t.parent_path(), ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= prefix.size() + extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            name.compare(name.size() - extension.size(), extension.size(), extension) != 0)
            continue;
        // "<pid>-<n>" between the prefix and the extension, digits only.
        const std::string_view middle =
            std::string_view(name).substr(prefix.size(), name.size() - prefix.size() - extension.size());
        const std::size_t dash = middle.find('-');
        if (dash == std::string_view::npos || !allDigits(middle.substr(0, dash)) || !allDigits(middle.substr(dash + 1)))
            continue;
        std::error_code sec;
        if (!fs::is_regular_file(it->symlink_status(sec)) || sec) continue;
        if (processAlive(std::stol(std::string(middle.substr(0, dash))))) continue;
        if (fs::remove(it->path(), sec) && !sec) removed.push_back(it->path().string());
    }
    return removed;
}

}  // namespace darkroom::movie
