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
    ~Error() override;
};

// Thrown (by the host) when a run was cancelled; never reported as a failure.
class DARKROOM_API Cancelled : public Error {
public:
    Cancelled();
    ~Cancelled() override;
};

}  // namespace darkroom
