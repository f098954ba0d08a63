#include <darkroom/error.h>

#include <utility>

namespace darkroom {

// Out-of-line destructors are the key functions: the type_info of these
// classes lives in the SDK library, so a plugin's throw is caught by the host.
Error::Error(const std::string& what) : std::runtime_error(what) {}
Error::Error(const std::string& what, std::string node) : std::runtime_error(what), node_(std::move(node)) {}
Error::~Error() = default;
InputError::InputError(const std::string& what) : Error(what) {}
InputError::InputError(const std::string& what, std::string node) : Error(what, std::move(node)) {}
InputError::~InputError() = default;
Cancelled::Cancelled() : Error("cancelled") {}
Cancelled::~Cancelled() = default;

}  // namespace darkroom
