#pragma once
// Checks of the in situ API's arguments that do not depend on the data:
// each throws BadInput (DARKROOM_INSITU_BAD_INPUT) naming the call and the
// argument, in one line. Bounds that depend on the scene's size are checked
// at capture time (session_setup.h, camera_bounds.h). docs/insitu.md,
// "Arguments".
#include <darkroom/error.h>
#include <darkroom/math.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace darkroom::insitu {

// A mistake in the arguments of a call (DARKROOM_INSITU_BAD_INPUT).
class BadInput : public Error {
public:
    using Error::Error;
};

// Most worker threads a session takes (a task arena allocates a slot per thread).
inline constexpr int kMaxThreads = 4096;
// Most phi or theta angles of an orbit: the scene file's limit on an angle count.
inline constexpr int kMaxAngles = 3600;
// Largest distance between vertex records: Embree keeps strides in 32 bits.
inline constexpr std::size_t kMaxStride = std::size_t(1) << 31;

// A name (object, field, database path): not empty, no control characters
// (they would break the one-line messages and the ranks' comparison of
// object lists).
void checkName(const char* call, const char* what, const std::string& name);
// 0 (off) or 1 (on).
bool checkSwitch(const char* call, const char* what, int on);
// Every coordinate finite.
void checkFinite(const char* call, const char* what, const Vec3& v);
// A direction: finite and not zero.
void checkDirection(const char* call, const char* what, const Vec3& v);
// Records `stride` bytes apart (0 = `fallback`): a multiple of 4, at least
// 12 (x, y, z), below kMaxStride. Returns the stride to use.
std::size_t checkStride(const char* call, const std::string& object, std::size_t stride, std::size_t fallback);
// The constant radius of lines and points: finite and not negative; positive
// when it is the one used.
void checkRadius(const char* call, const std::string& object, float radius, bool used);
// Radii, `count` of them `stride` bytes apart: each finite and not negative.
void checkRadii(const char* call, const std::string& object, const float* radii, std::size_t stride,
                std::int64_t count);

}  // namespace darkroom::insitu
