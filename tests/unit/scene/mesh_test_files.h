#pragma once
// Helpers for the reader tests: typed bytes in either byte order, base64 and
// zlib as VTK writes them, and an assertion on error messages.
#include <darkroom/error.h>
#include <darkroom/scene.h>
#include <gtest/gtest.h>

#include <dlfcn.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace darkroom::test {

template <class T>
void put(std::string& out, T v, bool bigEndian) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    // The test hosts are little-endian (x86-64, aarch64).
    if (bigEndian)
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    out.append(b, sizeof(T));
}

template <class T>
std::string bytesOf(const std::vector<T>& v, bool bigEndian = false) {
    std::string s;
    for (const T& x : v) put(s, x, bigEndian);
    return s;
}

inline std::string base64(const std::string& in) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const unsigned v = unsigned(std::uint8_t(in[i])) << 16 | unsigned(std::uint8_t(in[i + 1])) << 8 | std::uint8_t(in[i + 2]);
        out += {abc[v >> 18], abc[v >> 12 & 63], abc[v >> 6 & 63], abc[v & 63]};
    }
    if (i + 1 == in.size()) {
        const unsigned v = unsigned(std::uint8_t(in[i])) << 16;
        out += {abc[v >> 18], abc[v >> 12 & 63], '=', '='};
    } else if (i + 2 == in.size()) {
        const unsigned v = unsigned(std::uint8_t(in[i])) << 16 | unsigned(std::uint8_t(in[i + 1])) << 8;
        out += {abc[v >> 18], abc[v >> 12 & 63], abc[v >> 6 & 63], '='};
    }
    return out;
}

// zlib's compress(). The test executables do not link zlib themselves (only
// the framework does, privately), so it is looked up in the loaded libz.
inline std::string zlibCompress(const std::string& in) {
    using Fn = int (*)(Bytef*, uLongf*, const Bytef*, uLong);
    static Fn fn = reinterpret_cast<Fn>(dlsym(RTLD_DEFAULT, "compress"));
    if (!fn) throw std::runtime_error("zlib compress() not found in the process");
    uLongf len = uLongf(in.size() + in.size() / 100 + 64);
    std::string out(len, '\0');
    if (fn(reinterpret_cast<Bytef*>(out.data()), &len, reinterpret_cast<const Bytef*>(in.data()), uLong(in.size())) != Z_OK)
        throw std::runtime_error("compress failed");
    out.resize(len);
    return out;
}

// Primitive count as SceneObject::primitiveCount() defines it (that member is
// not exported from the SDK library, so tests cannot link against it).
inline std::size_t primitives(const SceneObject& o) {
    switch (o.representation) {
        case Representation::Surface: return o.indices.size() / 3;
        case Representation::Lines: return o.indices.size();
        case Representation::Points: return o.vertexCount();
    }
    return 0;
}

// Asserts that fn throws darkroom::Error whose message contains every part.
inline void expectError(const std::function<void()>& fn, const std::vector<std::string>& parts) {
    try {
        fn();
        ADD_FAILURE() << "expected darkroom::Error containing '" << parts.front() << "'";
    } catch (const darkroom::Error& e) {
        const std::string msg = e.what();
        for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
    }
}

// Asserts that fn throws InputError (not only Error) with every part, on one line.
inline void expectInputError(const std::function<void()>& fn, const std::vector<std::string>& parts) {
    try {
        fn();
        ADD_FAILURE() << "expected darkroom::InputError containing '" << parts.front() << "'";
    } catch (const darkroom::InputError& e) {
        const std::string msg = e.what();
        for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
    }
}

}  // namespace darkroom::test
