#pragma once
// For tests of refused input and failed writes: the message of the darkroom::InputError that
// `fn` throws, checked to be one line; "" and a test failure when it throws
// something else or nothing.
#include <darkroom/error.h>

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace darkroom::test {

inline std::string inputError(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const InputError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
        return msg;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no error";
    return {};
}

// The message of the darkroom::Error (of any kind) `fn` throws, or
// "(no error)".
inline std::string errorOf(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace darkroom::test
