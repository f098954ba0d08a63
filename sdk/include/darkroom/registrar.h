#pragma once
#include <darkroom/capture_backend.h>
#include <darkroom/export.h>
#include <darkroom/filter.h>

#include <functional>
#include <memory>
#include <string>

namespace darkroom {

struct FilterInfo {
    std::string type;      // unique type name, e.g. "ColorMapping"
    std::string category;  // palette group, e.g. "Color", "Lighting", "Input/Output"
    std::string doc;       // one paragraph shown by `darkroom describe` and the editor
    std::function<std::unique_ptr<Filter>()> create;
};

struct CaptureBackendInfo {
    std::string type;  // e.g. "embree"
    std::string doc;
    std::function<std::unique_ptr<CaptureBackend>()> create;
};

// Handed to a plugin's register function. Registrations become visible only
// if the whole register function succeeds.
class DARKROOM_API Registrar {
public:
    virtual ~Registrar();
    virtual void addFilter(FilterInfo info) = 0;
    virtual void addCaptureBackend(CaptureBackendInfo info) = 0;

    template <class F>
    void addFilter(std::string type, std::string category, std::string doc) {
        addFilter(FilterInfo{std::move(type), std::move(category), std::move(doc),
                             [] { return std::unique_ptr<Filter>(new F()); }});
    }
};

}  // namespace darkroom
