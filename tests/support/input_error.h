#pragma once
// For tests of refused input: the message of the darkroom::InputError that
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

}  // namespace darkroom::test
