#include "thumbnail_sources.h"

#include "cinema_entries.h"
#include "evaluator_adapter.h"
#include "preview_graph.h"

#include <darkroom/error.h>

namespace editor {
namespace {

class ProductSource : public ThumbnailSource {
public:
    ProductSource(const darkroom::Registry& registry, const std::string& database,
                  std::shared_ptr<const std::vector<std::size_t>> rows)
        : reader_(registry, database), rows_(std::move(rows)) {}
    QImage make(std::size_t item, int size) override {
        return thumbnail(*reader_.read(rows_->at(item)), size);
    }

private:
    CinemaEntryReader reader_;
    std::shared_ptr<const std::vector<std::size_t>> rows_;
};

class PipelineSource : public ThumbnailSource {
public:
    PipelineSource(const PipelineThumbnails& spec, std::shared_ptr<const std::vector<std::size_t>> rows)
        : spec_(spec), rows_(std::move(rows)), adapter_(1, std::size_t(256) << 20) {
        adapter_.setInputBase(spec_.inputBase);
    }
    QImage make(std::size_t item, int size) override {
        darkroom::Graph g = *spec_.graph;
        g.setParameter(spec_.reader, "entry", darkroom::Value(std::int64_t(rows_->at(item))));
        if (spec_.level < 0) {  // the products' size, from the first one read
            const darkroom::BufferPtr source = adapter_.evaluate(g, spec_.reader, "image", {}, nullptr);
            spec_.level = source ? thumbnailLevel(source->width(), size) : 0;
        }
        const darkroom::Graph run = spec_.level > 0 ? makePreviewGraph(g, spec_.level) : g;
        const darkroom::BufferPtr b = adapter_.evaluate(run, spec_.node, spec_.port, {}, nullptr);
        if (!b) throw darkroom::Error("node '" + spec_.node + "' gave no image");
        return thumbnail(*b, size);
    }

private:
    PipelineThumbnails spec_;
    std::shared_ptr<const std::vector<std::size_t>> rows_;
    EvaluatorAdapter adapter_;
};

}  // namespace

ThumbnailSourceFactory productThumbnails(const darkroom::Registry& registry, std::string database,
                                         std::vector<std::size_t> rows) {
    auto shared = std::make_shared<const std::vector<std::size_t>>(std::move(rows));
    const darkroom::Registry* r = &registry;
    return [r, database, shared] { return std::make_unique<ProductSource>(*r, database, shared); };
}

ThumbnailSourceFactory pipelineThumbnails(PipelineThumbnails spec, std::vector<std::size_t> rows) {
    auto shared = std::make_shared<const std::vector<std::size_t>>(std::move(rows));
    return [spec, shared] { return std::make_unique<PipelineSource>(spec, shared); };
}

int thumbnailLevel(int width, int thumbnailSize) {
    int level = 0;
    while (level < 5 && (width >> (level + 1)) >= 2 * thumbnailSize) ++level;
    return level;
}

}  // namespace editor
