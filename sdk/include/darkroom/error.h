#pragma once
#include <darkroom/export.h>

#include <stdexcept>
#include <string>

namespace darkroom {

// The one exception type the host and plugins throw for expected failures
// (bad input, missing channel, unreadable file). Its message is shown to the
// user as is, so it names what was wrong and what was expected.
class DARKROOM_API Error : public std::runtime_error {
public:
    explicit Error(const std::string& what);
    // An error the host attributes to a node: `what` already says which (the
    // host writes "node 'name' (Type): ..."); `node` is the name, as data, for
    // a UI to mark that node without reading the message.
    Error(const std::string& what, std::string node);
    ~Error() override;
    // The failing node's name; empty when the error is no node's.
    const std::string& node() const noexcept { return node_; }

private:
    std::string node_;
};

// Bad input: a file, pipeline, value or size that is wrong or beyond a limit
// (darkroom/limits.h). The runner exits 2 for it, as `validate` does for a
// bad pipeline; the message names the file, line or node and what was expected.
class DARKROOM_API InputError : public Error {
public:
    explicit InputError(const std::string& what);
    InputError(const std::string& what, std::string node);
    ~InputError() override;
};

// Thrown (by the host) when a run was cancelled; never reported as a failure.
class DARKROOM_API Cancelled : public Error {
public:
    Cancelled();
    ~Cancelled() override;
};

}  // namespace darkroom
