// The in situ API's argument checks (darkroom/insitu.h). The input is a
// script, one C API call a line, so that the committed corpus is text a
// reviewer can read (tests/fuzz/corpus/insitu/):
//
//   open MODE [SUFFIX]          session on <scratch>/insitu/db<SUFFIX>.cdb (closes the last)
//   image W H FOV HEIGHT        set_image          orbit T DIST U NPHI NTHETA   camera_orbit
//   camera P T U                add_camera         (T, U, P: x y z, or - for NULL)
//   request NAME | normals N | ids A B | half N | threads N | mpi N
//   step TIME                   begin_step         capture | close | error TEXT | stats
//   triangles NAME STRIDE NV NT             lines NAME STRIDE NV NS RADIUS [radii]
//   points NAME STRIDE NV RADIUS [radii]    field OBJECT NAME COUNT ASSOCIATION
//   vertices X... | indices I... | radii R... | values V... | phi A... | theta A...
//                               fill the arrays the harness owns (- alone: pass NULL)
//
// Numbers are read by strtod (nan, inf, 1e300, 0x1p-1074), integers
// saturate, NAME and TEXT are "quoted" with C escapes (\n, \x01) or a bare
// word. What the API cannot check, the harness keeps to: no array is read
// past its end (a count or stride that would read further is clamped,
// unless the API must refuse it before reading: negative, beyond 2^32 - 1,
// a stride of 2^31 or more, more than 3600 angles). Images stay at most
// 4 x 4 pixels (a session starts with `image 4 4 30 0`), a session has at most 4 listed cameras or 2 x 2 orbit
// views, and an input at most 2 captures (later `capture` lines are
// skipped), so an input costs a few milliseconds.
//
// A finding: a crash, a sanitizer report, an abort (Embree's assertions
// included), a status other than 0, 1 or 2, a failed call with no message,
// or a message of more than one line. With DARKROOM_FUZZ_TRACE set, every
// call's line, status and message go to stderr (to read what a unit does).
#include "harness.h"

#include <darkroom/insitu.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

constexpr std::size_t kRecords = 16;  // x, y, z, radius records the vertex array holds
// Bounds on what one input may cost (a capture with its database writes
// costs about a millisecond under the sanitizers, each camera more).
constexpr int kMaxSide = 4, kMaxListed = 4, kMaxAngles = 2, kMaxCaptures = 2, kMaxCalls = 64;

// The arrays the sessions read: filled by the script, alive until the last
// session is closed.
struct Arrays {
    std::array<float, 4 * kRecords + 1> vertices{};  // + 4 spare bytes for Embree's 16-byte loads
    std::array<std::uint32_t, 3 * kRecords> indices{};
    std::array<float, kRecords> radii{}, values{};
    std::array<double, 8> phi{}, theta{};
    bool noVertices = false, noIndices = false, noValues = false, noAngles = false;
};

// One line's tokens.
class Line {
public:
    explicit Line(const std::string& text) : text_(text) {}

    bool done() {
        skipSpace();
        return at_ >= text_.size();
    }
    std::string word() {
        skipSpace();
        if (at_ < text_.size() && text_[at_] == '"') return quoted();
        const std::size_t start = at_;
        while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
        return text_.substr(start, at_ - start);
    }
    double number() { return std::strtod(word().c_str(), nullptr); }
    std::int64_t integer() {
        return std::strtoll(word().c_str(), nullptr, 0);  // saturates at the int64 limits
    }
    int smallInt() {
        return int(std::clamp<std::int64_t>(integer(), std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
    }
    // x y z, or - for NULL.
    const double* vec(std::array<double, 3>& v) {
        skipSpace();
        if (text_.compare(at_, 1, "-") == 0 && (at_ + 1 >= text_.size() || std::isspace(static_cast<unsigned char>(text_[at_ + 1])))) {
            ++at_;
            return nullptr;
        }
        for (double& x : v) x = number();
        return v.data();
    }

private:
    void skipSpace() {
        while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    }
    std::string quoted() {
        std::string out;
        for (++at_; at_ < text_.size() && text_[at_] != '"'; ++at_) {
            if (text_[at_] != '\\' || at_ + 1 >= text_.size()) {
                out += text_[at_];
                continue;
            }
            const char e = text_[++at_];
            if (e == 'n') out += '\n';
            else if (e == 'r') out += '\r';
            else if (e == 't') out += '\t';
            else if (e == 'x' && at_ + 2 < text_.size()) {
                out += char(std::strtol(text_.substr(at_ + 1, 2).c_str(), nullptr, 16));
                at_ += 2;
            } else out += e;
        }
        if (at_ < text_.size()) ++at_;  // the closing quote, when there is one
        return out;
    }
    const std::string& text_;
    std::size_t at_ = 0;
};

[[noreturn]] void finding(const char* what, int code, const char* error) {
    std::fprintf(stderr, "insitu harness: %s (status %d, error '%s')\n", what, code, error);
    std::abort();
}

void checkStatus(int code, const char* error) {
    if (code != DARKROOM_INSITU_OK && code != DARKROOM_INSITU_FAILED && code != DARKROOM_INSITU_BAD_INPUT)
        finding("an undocumented status", code, error);
}

const std::string* traced = nullptr;  // the line being run, when tracing

// A call's status is one the header documents; a failure says why, in one line.
void checked(darkroom_insitu* s, int code) {
    const char* e = darkroom_insitu_error(s);
    if (traced) std::fprintf(stderr, "%-40s -> %d %s\n", traced->c_str(), code, e);
    checkStatus(code, e);
    if (code != DARKROOM_INSITU_OK && (!e || !*e)) finding("a failure without a message", code, e);
    for (const char* p = e; p && *p; ++p)
        if (*p == '\n') finding("a message of more than one line", code, e);
}

// A count of elements of an array holding `capacity`: kept when it fits or
// when the API refuses it unread (negative, beyond 2^32 - 1), else clamped.
std::int64_t fit(std::int64_t count, std::size_t capacity) {
    if (count < 0 || count > std::int64_t(0xFFFFFFFFu)) return count;
    return std::min<std::int64_t>(count, std::int64_t(capacity));
}

// Vertex records `stride` bytes apart (0: `fallback`) read 16 bytes each.
std::int64_t fitVertices(std::int64_t count, std::size_t stride, std::size_t fallback) {
    const std::size_t s = stride ? stride : fallback;
    if (s < 12 || s % 4 != 0 || s >= (std::size_t(1) << 31)) return count;  // refused before reading
    return fit(count, (sizeof(Arrays::vertices) - 16) / s + 1);
}

std::size_t stride(Line& l) {
    const std::int64_t v = l.integer();
    return static_cast<std::size_t>(v);  // negative: a huge size_t, as a C caller's mistake would give
}

template <class T, std::size_t N>
void fill(Line& l, std::array<T, N>& a, bool& none) {
    none = l.done();
    for (std::size_t i = 0; i < N && !l.done(); ++i) {
        const std::string w = l.word();
        if (w == "-") {
            none = true;
            break;
        }
        a[i] = std::is_floating_point_v<T> ? T(std::strtod(w.c_str(), nullptr)) : T(std::strtoull(w.c_str(), nullptr, 0));
    }
}

struct Session {
    darkroom_insitu* s = nullptr;
    Arrays& a;
    int listed = 0;    // in this session
    int captures = 0;  // in this input

    void close() {
        if (!s) return;
        const int code = darkroom_insitu_close(s);  // frees s: no message to read
        checkStatus(code, "");
        s = nullptr;
    }
};

int angleCount(Line& l) {
    const int n = l.smallInt();
    return n < 0 || n > 3600 ? n : std::min(n, kMaxAngles);
}

void objects(Session& x, const std::string& call, Line& l) {
    Arrays& a = x.a;
    const std::string name = l.word();
    const std::size_t st = stride(l);
    const float* v = a.noVertices ? nullptr : a.vertices.data();
    const std::uint32_t* idx = a.noIndices ? nullptr : a.indices.data();
    if (call == "triangles") {
        const std::int64_t nv = fitVertices(l.integer(), st, 12), nt = fit(l.integer(), kRecords);
        checked(x.s, darkroom_insitu_triangles(x.s, name.c_str(), v, st, nv, idx, nt));
    } else if (call == "lines") {
        const std::int64_t nv = fitVertices(l.integer(), st, 16), ns = fit(l.integer(), 3 * kRecords);
        const float radius = float(l.number());
        const float* radii = l.word() == "radii" ? a.radii.data() : nullptr;
        checked(x.s, darkroom_insitu_lines(x.s, name.c_str(), v, st, radii ? fit(nv, kRecords) : nv, idx, ns, radii, radius));
    } else {
        const std::int64_t nv = fitVertices(l.integer(), st, 16);
        const float radius = float(l.number());
        const float* radii = l.word() == "radii" ? a.radii.data() : nullptr;
        checked(x.s, darkroom_insitu_points(x.s, name.c_str(), v, st, radii ? fit(nv, kRecords) : nv, radii, radius));
    }
}

void setup(Session& x, const std::string& call, Line& l) {
    std::array<double, 3> p{}, t{}, u{};
    if (call == "image") {
        auto side = [&] {
            const int v = l.smallInt();
            return v > kMaxSide && v <= 65536 ? kMaxSide : v;
        };
        const int w = side(), h = side();
        const double fov = l.number(), height = l.number();
        checked(x.s, darkroom_insitu_set_image(x.s, w, h, fov, height));
    } else if (call == "orbit") {
        const double* target = l.vec(t);
        const double distance = l.number();
        const double* up = l.vec(u);
        const int np = angleCount(l), nt = angleCount(l);
        const double* phi = x.a.noAngles ? nullptr : x.a.phi.data();
        const double* theta = x.a.noAngles ? nullptr : x.a.theta.data();
        checked(x.s, darkroom_insitu_camera_orbit(x.s, target, distance, up, phi, np, theta, nt));
    } else if (call == "camera" && x.listed < kMaxListed) {
        ++x.listed;
        const double* position = l.vec(p);
        const double* target = l.vec(t);
        const double* up = l.vec(u);
        checked(x.s, darkroom_insitu_add_camera(x.s, position, target, up));
    } else if (call == "request") {
        const std::string name = l.word();
        checked(x.s, darkroom_insitu_request_field(x.s, name == "-" ? nullptr : name.c_str()));
    } else if (call == "normals") {
        checked(x.s, darkroom_insitu_request_normals(x.s, l.smallInt()));
    } else if (call == "ids") {
        const int o = l.smallInt(), p2 = l.smallInt();
        checked(x.s, darkroom_insitu_request_ids(x.s, o, p2));
    } else if (call == "half") {
        checked(x.s, darkroom_insitu_set_half_float(x.s, l.smallInt()));
    } else if (call == "threads") {
        const int n = l.smallInt();
        checked(x.s, darkroom_insitu_set_threads(x.s, n > 4 && n <= 4096 ? 4 : n));  // valid and costly: 4
    } else if (call == "mpi") {
        checked(x.s, darkroom_insitu_set_mpi_comm(x.s, l.smallInt()));
    }
}

void run(Session& x, const std::string& call, Line& l) {
    Arrays& a = x.a;
    if (call == "vertices") fill(l, a.vertices, a.noVertices);
    else if (call == "indices") fill(l, a.indices, a.noIndices);
    else if (call == "radii") {
        bool unused = false;
        fill(l, a.radii, unused);
    } else if (call == "values") fill(l, a.values, a.noValues);
    else if (call == "phi") fill(l, a.phi, a.noAngles);
    else if (call == "theta") fill(l, a.theta, a.noAngles);
    else if (call == "step") checked(x.s, darkroom_insitu_begin_step(x.s, l.number()));
    else if (call == "triangles" || call == "lines" || call == "points") objects(x, call, l);
    else if (call == "field") {
        const std::string object = l.word(), name = l.word();
        const std::int64_t count = fit(l.integer(), kRecords);
        const int association = l.smallInt();
        checked(x.s, darkroom_insitu_field(x.s, object.c_str(), name.c_str(), a.noValues ? nullptr : a.values.data(),
                                           count, association));
    } else if (call == "capture") {
        if (x.captures++ < kMaxCaptures) checked(x.s, darkroom_insitu_capture(x.s));
    }
    else if (call == "error") {
        const std::string text = l.word();
        checked(x.s, darkroom_insitu_report_error(x.s, text.c_str()));  // BAD_INPUT, and still one line
    } else if (call == "stats") {
        (void)darkroom_insitu_copied_bytes(x.s);
        (void)darkroom_insitu_rows_written(x.s);
    } else setup(x, call, l);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path folder = std::filesystem::path(fuzz::scratchFolder()) / "insitu";
    std::error_code ec;
    std::filesystem::remove_all(folder, ec);
    std::filesystem::create_directories(folder, ec);
    static const bool trace = std::getenv("DARKROOM_FUZZ_TRACE") != nullptr;
    std::istringstream script{std::string(fuzz::text(data, size))};
    Arrays arrays;
    Session x{nullptr, arrays};
    int calls = 0;
    for (std::string text; calls < kMaxCalls && std::getline(script, text);) {
        Line l(text);
        if (trace) traced = &text;
        const std::string call = l.word();
        if (call.empty() || call[0] == '#') continue;
        ++calls;
        if (call == "open") {
            x.close();
            const int mode = l.smallInt();
            std::string suffix = l.word();
            suffix.erase(std::remove(suffix.begin(), suffix.end(), '/'), suffix.end());  // stays in the folder
            x.listed = 0;
            x.s = darkroom_insitu_open(((folder / "db").string() + suffix + ".cdb").c_str(), mode);
            if (!x.s) return 0;  // out of memory
            checked(x.s, DARKROOM_INSITU_OK);
            // Tiny images from the start: the default is 512 x 512.
            checked(x.s, darkroom_insitu_set_image(x.s, kMaxSide, kMaxSide, 30.0, 0.0));
        } else if (call == "close") {
            x.close();
        } else if (x.s) {
            run(x, call, l);
        }
    }
    x.close();
    std::filesystem::remove_all(folder, ec);
    return 0;
}
