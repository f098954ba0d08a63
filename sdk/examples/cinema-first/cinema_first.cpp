// Example pass of a plugin that links the data library: the product of a
// Cinema database's first entry (Spec D: data.csv and its FILE column), read
// with the host's own database and image readers.
#include <darkroom/darkroom.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/image_io.h>

namespace {

class CinemaFirst final : public darkroom::Filter {
    darkroom::PathIn database{"database", "", "A Cinema database: a .cdb folder or its data.csv"};
    darkroom::ImageOut result{"image", "The first entry's product"};

public:
    darkroom::PortList ports() const override { return {database, result}; }

    void execute(darkroom::Context& ctx) override {
        const auto db = darkroom::CinemaDatabase::open(ctx.get(database));
        if (db.rowCount() == 0) throw darkroom::InputError(ctx.get(database) + ": the database has no entries");
        const std::string product = db.productPath(0);
        ctx.readsFile(product);
        ctx.set(result, darkroom::readImage(product));
    }
};

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<CinemaFirst>("CinemaFirst", "Input", "The first entry of a Cinema database (SDK example plugin).");
}

}  // namespace

DARKROOM_PLUGIN("cinema-first-example", "1.0.0", registerTypes)
