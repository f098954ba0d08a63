#pragma once
// An OpenEXR output stream into memory. The EXR writer encodes a whole file
// here and hands the bytes to writeFileAtomic, whose every write, fsync and
// close is checked: OpenEXR's own file stream writes the offset table from
// OutputFile's destructor, where a failed write is swallowed.
#include <ImfIO.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace darkroom::io {

class ExrMemoryStream final : public Imf::OStream {
public:
    explicit ExrMemoryStream(const std::string& name) : Imf::OStream(name.c_str()) {}

    void write(const char c[], int n) override {
        const std::size_t end = position_ + std::size_t(n);
        if (end > bytes_.size()) bytes_.resize(end);
        std::memcpy(bytes_.data() + position_, c, std::size_t(n));
        position_ = end;
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = std::size_t(position); }

    const std::string& bytes() const { return bytes_; }

private:
    std::string bytes_;
    std::size_t position_ = 0;
};

}  // namespace darkroom::io
