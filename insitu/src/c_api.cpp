// The C API of darkroom/insitu.h: one error boundary around Session, so no
// C++ exception ever reaches a C or Fortran caller.
#include "session.h"

#include <darkroom/insitu.h>

#include <exception>
#include <new>

struct darkroom_insitu {
    std::unique_ptr<darkroom::insitu::Session> session;
    std::string error;
    std::string openError;  // a session that could not be opened keeps failing with this
};

namespace {

using darkroom::insitu::BadInput;

// darkroom_insitu_error promises one line: control characters (a line
// break in an OS message, a binding's text) become spaces.
std::string oneLine(std::string message) {
    for (char& c : message)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    return message;
}

template <class F>
int guarded(darkroom_insitu* s, F&& f) {
    if (!s) return DARKROOM_INSITU_BAD_INPUT;
    if (!s->openError.empty()) {
        s->error = s->openError;
        return DARKROOM_INSITU_BAD_INPUT;
    }
    s->error.clear();
    try {
        f(*s->session);
        return DARKROOM_INSITU_OK;
    } catch (const BadInput& e) {
        s->error = oneLine(e.what());
        return DARKROOM_INSITU_BAD_INPUT;
    } catch (const std::bad_alloc&) {
        s->error = "out of memory";
    } catch (const std::exception& e) {
        s->error = oneLine(e.what());
    } catch (...) {
        s->error = "unknown error";
    }
    return DARKROOM_INSITU_FAILED;
}

std::string text(const char* s) { return s ? std::string(s) : std::string(); }

darkroom::Vec3 vec(const double* v) { return v ? darkroom::Vec3{v[0], v[1], v[2]} : darkroom::Vec3{0, 0, 0}; }

}  // namespace

extern "C" {

darkroom_insitu* darkroom_insitu_open(const char* database, int mode) {
    auto* s = new (std::nothrow) darkroom_insitu;
    if (!s) return nullptr;
    try {
        s->session = std::make_unique<darkroom::insitu::Session>(text(database), mode);
    } catch (const std::exception& e) {
        s->openError = oneLine(e.what());
        s->error = s->openError;
    }
    return s;
}

int darkroom_insitu_set_mpi_comm(darkroom_insitu* s, int fortranComm) {
    return guarded(s, [&](auto& x) { x.setRanks(darkroom::insitu::mpiRanks(fortranComm)); });
}

int darkroom_insitu_set_threads(darkroom_insitu* s, int threads) {
    return guarded(s, [&](auto& x) { x.setThreads(threads); });
}

int darkroom_insitu_set_image(darkroom_insitu* s, int width, int height, double fov, double viewHeight) {
    return guarded(s, [&](auto& x) { x.setup().setImage(width, height, fov, viewHeight); });
}

int darkroom_insitu_camera_orbit(darkroom_insitu* s, const double target[3], double distance, const double up[3],
                                 const double* phi, int phiCount, const double* theta, int thetaCount) {
    return guarded(s, [&](auto& x) {
        const char* call = "darkroom_insitu_camera_orbit";
        for (const auto& [count, what] : {std::pair{phiCount, "phi_count"}, std::pair{thetaCount, "theta_count"}})
            if (count < 1 || count > darkroom::insitu::kMaxAngles)
                throw BadInput(std::string(call) + ": " + what + " " + std::to_string(count) + "; expected 1 to " +
                               std::to_string(darkroom::insitu::kMaxAngles));
        if (!target || !up || !phi || !theta) throw BadInput(std::string(call) + ": missing target, up or angle arrays");
        x.setup().cameraOrbit(vec(target), distance, vec(up), std::vector<double>(phi, phi + phiCount),
                      std::vector<double>(theta, theta + thetaCount));
    });
}

int darkroom_insitu_add_camera(darkroom_insitu* s, const double position[3], const double target[3],
                               const double up[3]) {
    return guarded(s, [&](auto& x) {
        if (!position || !target || !up) throw BadInput("darkroom_insitu_add_camera: missing position, target or up");
        x.setup().addCamera(vec(position), vec(target), vec(up));
    });
}

int darkroom_insitu_request_field(darkroom_insitu* s, const char* name) {
    return guarded(s, [&](auto& x) { x.setup().requestField(text(name)); });
}

int darkroom_insitu_request_normals(darkroom_insitu* s, int on) {
    return guarded(s, [&](auto& x) { x.setup().requestNormals(on); });
}

int darkroom_insitu_request_ids(darkroom_insitu* s, int objectIds, int primitiveIds) {
    return guarded(s, [&](auto& x) { x.setup().requestIds(objectIds, primitiveIds); });
}

int darkroom_insitu_set_half_float(darkroom_insitu* s, int on) {
    return guarded(s, [&](auto& x) { x.setup().setHalfFloat(on); });
}

int darkroom_insitu_begin_step(darkroom_insitu* s, double time) {
    return guarded(s, [&](auto& x) { x.beginStep(time); });
}

int darkroom_insitu_triangles(darkroom_insitu* s, const char* name, const float* vertices, size_t stride,
                              int64_t vertexCount, const uint32_t* triangles, int64_t triangleCount) {
    return guarded(s, [&](auto& x) { x.triangles(text(name), vertices, stride, vertexCount, triangles, triangleCount); });
}

int darkroom_insitu_lines(darkroom_insitu* s, const char* name, const float* vertices, size_t stride,
                          int64_t vertexCount, const uint32_t* segments, int64_t segmentCount, const float* radii,
                          float radius) {
    return guarded(s, [&](auto& x) {
        x.lines(text(name), vertices, stride, vertexCount, segments, segmentCount, radii, radius);
    });
}

int darkroom_insitu_points(darkroom_insitu* s, const char* name, const float* vertices, size_t stride,
                           int64_t vertexCount, const float* radii, float radius) {
    return guarded(s, [&](auto& x) { x.points(text(name), vertices, stride, vertexCount, radii, radius); });
}

int darkroom_insitu_field(darkroom_insitu* s, const char* object, const char* name, const float* values,
                          int64_t count, int association) {
    return guarded(s, [&](auto& x) { x.field(text(object), text(name), values, count, association); });
}

int darkroom_insitu_capture(darkroom_insitu* s) {
    return guarded(s, [&](auto& x) { x.capture(); });
}

int darkroom_insitu_close(darkroom_insitu* s) {
    if (!s) return DARKROOM_INSITU_OK;
    int code = s->openError.empty() ? DARKROOM_INSITU_OK : DARKROOM_INSITU_BAD_INPUT;
    if (s->session) code = guarded(s, [&](auto& x) { x.close(); });
    delete s;
    return code;
}

const char* darkroom_insitu_error(const darkroom_insitu* s) {
    if (!s) return "no session (darkroom_insitu_open returned NULL: out of memory)";
    return s->error.c_str();
}

int64_t darkroom_insitu_copied_bytes(const darkroom_insitu* s) {
    return s && s->session ? s->session->copiedBytes() : 0;
}

int64_t darkroom_insitu_rows_written(const darkroom_insitu* s) {
    return s && s->session ? s->session->rowsWritten() : 0;
}

int darkroom_insitu_report_error(darkroom_insitu* s, const char* message) {
    // Every failure says something (a NULL or empty message too).
    if (s) s->error = message && *message ? oneLine(message) : "an error without a message (darkroom_insitu_report_error)";
    return DARKROOM_INSITU_BAD_INPUT;
}

}  // extern "C"
