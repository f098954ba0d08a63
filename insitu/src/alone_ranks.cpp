// A session without MPI: one process holds everything.
#include "ranks.h"

#include <darkroom/error.h>

namespace darkroom::insitu {

namespace {

class Alone final : public Ranks {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    int onThisNode() const override { return 1; }
    std::vector<std::string> allGather(const std::string& mine) override { return {mine}; }
    void broadcast(std::string&) override {}
    std::string agreedError(const std::string& mine) override { return mine; }
    std::vector<std::uint64_t> exclusiveSums(const std::vector<std::uint64_t>& counts) override {
        return std::vector<std::uint64_t>(counts.size(), 0);
    }
    BufferPtr composite(const Buffer&, const std::vector<std::uint64_t>&, bool, bool) override {
        throw Error("in situ: compositing needs several ranks");
    }
};

}  // namespace

std::unique_ptr<Ranks> aloneRanks() { return std::make_unique<Alone>(); }

}  // namespace darkroom::insitu
