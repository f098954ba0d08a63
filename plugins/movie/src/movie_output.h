#pragma once
// Where Movie writes: the `path` port as a file (never an FFmpeg URL such as
// pipe:1), kept inside the run's output folder, and the temporaries that
// killed runs left beside it.
#include <string>
#include <vector>

namespace darkroom {
class Context;
}

namespace darkroom::movie {

// The movie file `given` names, absolute, resolved as every output is
// (Context::resolveOutputPath). When the run has an output folder of its own
// (the runner's --output, told apart from the pipeline's folder), a path that
// leaves it — "..", an absolute path elsewhere, a symbolic link to elsewhere
// on the way — is refused with darkroom::InputError naming path and folder.
std::string resolveMoviePath(const Context& ctx, const std::string& given);

// The URL FFmpeg is given for a plain file path: the path, made absolute,
// behind FFmpeg's "file:" protocol, so that nothing in it is read as another
// protocol ("pipe:1") or option.
std::string fileUrl(const std::string& path);

// Removes the temporaries of `target` that runs killed while writing it left
// behind: regular files named exactly as temporaryPathFor(target) names them
// (<stem>.tmp-<pid>-<n><extension>, darkroom/atomic_file.h) whose pid is no
// live process of this machine and not this one. Returns the removed paths.
std::vector<std::string> removeStaleTemporaries(const std::string& target);

}  // namespace darkroom::movie
