#include <darkroom/error.h>

namespace darkroom {

// Out-of-line destructors are the key functions: the type_info of these
// classes lives in the SDK library, so a plugin's throw is caught by the host.
Error::Error(const std::string& what) : std::runtime_error(what) {}
Error::~Error() = default;
InputError::InputError(const std::string& what) : Error(what) {}
InputError::~InputError() = default;
Cancelled::Cancelled() : Error("cancelled") {}
Cancelled::~Cancelled() = default;

}  // namespace darkroom
