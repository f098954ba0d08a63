#pragma once
// Symbol visibility: everything is hidden by default (-fvisibility=hidden);
// what the SDK library and plugins must share is marked explicitly.
#if defined(_WIN32)
#define DARKROOM_EXPORT __declspec(dllexport)
#else
#define DARKROOM_EXPORT __attribute__((visibility("default")))
#endif

// The SDK library's own API: exported when building it, default-visible when used.
#define DARKROOM_API DARKROOM_EXPORT
