#include "tracked_buffer.h"

namespace darkroom {

const BufferPtr& TrackedBuffer::unwrap(const BufferPtr& b) {
    if (auto* t = dynamic_cast<const TrackedBuffer*>(b.get())) return t->inner_;
    return b;
}

bool TrackedBuffer::origin(const Buffer* b, std::string& port, int& index) {
    auto* t = dynamic_cast<const TrackedBuffer*>(b);
    if (!t) return false;
    port = t->port_;
    index = t->index_;
    return true;
}

}  // namespace darkroom
