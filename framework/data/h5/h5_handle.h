#pragma once
// Owning HDF5 identifiers and the library set-up every entry point of the
// .h5 format needs. Internal; the only header that includes hdf5.h, and only
// the format's .cpp files include it.
#include <hdf5.h>

#include <string>

namespace darkroom::h5 {

// An HDF5 identifier closed by its own close function when it goes out of scope.
class Handle {
public:
    using Close = herr_t (*)(hid_t);
    Handle() = default;
    Handle(hid_t id, Close close) : id_(id), close_(close) {}
    ~Handle() { reset(); }
    Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = o.id_;
            close_ = o.close_;
            o.id_ = -1;
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }

private:
    void reset() {
        if (id_ >= 0 && close_) close_(id_);
        id_ = -1;
    }
    hid_t id_ = -1;
    Close close_ = nullptr;
};

// Called before any HDF5 call on this thread: no error stack printed to
// stderr (failures become our exceptions), and no filter plugins loaded from
// HDF5_PLUGIN_PATH because a file names an unknown filter.
void prepareLibrary();

// A name for an in-memory (core driver) file that no other open file of
// this process has.
std::string uniqueMemoryName(const char* purpose);

}  // namespace darkroom::h5
