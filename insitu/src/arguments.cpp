#include "arguments.h"

#include <darkroom/scene/camera_bounds.h>

#include <cmath>

namespace darkroom::insitu {

namespace {

using camera_bounds::shortNumber;

std::string text(const Vec3& v) {
    return "[" + shortNumber(v.x) + ", " + shortNumber(v.y) + ", " + shortNumber(v.z) + "]";
}

}  // namespace

void checkName(const char* call, const char* what, const std::string& name) {
    if (name.empty()) throw BadInput(std::string(call) + ": the " + what + " is empty");
    for (std::size_t i = 0; i < name.size(); ++i) {
        const auto c = static_cast<unsigned char>(name[i]);
        if (c < 0x20 || c == 0x7f)
            throw BadInput(std::string(call) + ": the " + what + " has a control character (code " +
                           std::to_string(int(c)) + ") at byte " + std::to_string(i) +
                           "; names are one line of printable text");
    }
}

bool checkSwitch(const char* call, const char* what, int on) {
    if (on != 0 && on != 1)
        throw BadInput(std::string(call) + ": " + what + " is " + std::to_string(on) + "; expected 0 (off) or 1 (on)");
    return on == 1;
}

void checkFinite(const char* call, const char* what, const Vec3& v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw BadInput(std::string(call) + ": " + what + " " + text(v) + " must be finite");
}

void checkDirection(const char* call, const char* what, const Vec3& v) {
    checkFinite(call, what, v);
    if (v.x == 0 && v.y == 0 && v.z == 0) throw BadInput(std::string(call) + ": " + what + " must not be zero");
}

std::size_t checkStride(const char* call, const std::string& object, std::size_t stride, std::size_t fallback) {
    if (stride == 0) stride = fallback;
    if (stride < 12 || stride % 4 != 0 || stride >= kMaxStride)
        throw BadInput(std::string(call) + ": object '" + object + "': vertices " + std::to_string(stride) +
                       " bytes apart; expected a multiple of 4 of at least 12 (x, y, z) and below 2^31");
    return stride;
}

void checkRadius(const char* call, const std::string& object, float radius, bool used) {
    if (!std::isfinite(radius) || radius < 0 || (used && !(radius > 0)))
        throw BadInput(std::string(call) + ": object '" + object + "': radius " + shortNumber(radius) +
                       (used ? "; give radii, records of x, y, z, radius, or a positive radius"
                             : "; expected a finite radius of 0 or more (0 when the records carry the radii)"));
}

void checkRadii(const char* call, const std::string& object, const float* radii, std::size_t stride,
                std::int64_t count) {
    for (std::int64_t i = 0; i < count; ++i) {
        const float r = *reinterpret_cast<const float*>(reinterpret_cast<const char*>(radii) + std::size_t(i) * stride);
        if (!std::isfinite(r) || r < 0)
            throw BadInput(std::string(call) + ": object '" + object + "': vertex " + std::to_string(i) +
                           " has radius " + shortNumber(r) + "; expected a finite radius of 0 or more");
    }
}

}  // namespace darkroom::insitu
