// Loading a scene over several processes (scene_partition.h), with threads
// standing in for MPI ranks: the shares add up to the whole scene primitive
// for primitive, ids line up, cameras and default radii are those of the
// whole scene, and a problem in one process's pieces fails every process.
#include "test_support.h"
#include "vtk_test_files.h"

#include <darkroom/error.h>
#include <darkroom/scene/mesh_readers.h>
#include <darkroom/scene/scene_file.h>
#include <darkroom/scene/scene_partition.h>

#include <gtest/gtest.h>

#include <barrier>
#include <functional>
#include <memory>
#include <thread>

using namespace darkroom;

namespace {

// allGather over threads: each writes its slot, all wait, all read.
class ThreadGroup final : public ProcessGroup {
public:
    struct Shared {
        explicit Shared(int n) : slots(std::size_t(n)), sync(n) {}
        std::vector<std::string> slots;
        std::barrier<> sync;
    };
    ThreadGroup(std::shared_ptr<Shared> shared, int rank) : shared_(std::move(shared)), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return int(shared_->slots.size()); }
    std::vector<std::string> allGather(const std::string& mine) override {
        shared_->slots[std::size_t(rank_)] = mine;
        shared_->sync.arrive_and_wait();
        std::vector<std::string> all = shared_->slots;
        shared_->sync.arrive_and_wait();
        return all;
    }

private:
    std::shared_ptr<Shared> shared_;
    int rank_;
};

// Runs `load` on `n` threads, one per rank; returns each rank's result or error.
struct RankResult {
    PartitionedScene scene;
    std::string error;
};
std::vector<RankResult> onRanks(int n, const std::function<PartitionedScene(ProcessGroup&)>& load) {
    auto shared = std::make_shared<ThreadGroup::Shared>(n);
    std::vector<RankResult> out(static_cast<std::size_t>(n));
    std::vector<std::thread> threads;
    for (int r = 0; r < n; ++r)
        threads.emplace_back([&, r] {
            ThreadGroup group(shared, r);
            try {
                out[std::size_t(r)].scene = load(group);
            } catch (const Error& e) {
                out[std::size_t(r)].error = e.what();
            }
        });
    for (auto& t : threads) t.join();
    return out;
}

// The vertices (x, y, z, radius) of primitive i, whatever the representation.
std::vector<float> primitive(const SceneObject& o, std::size_t i) {
    std::vector<std::uint32_t> v;
    switch (o.representation) {
        case Representation::Surface: v = {o.indices[3 * i], o.indices[3 * i + 1], o.indices[3 * i + 2]}; break;
        case Representation::Lines: v = {o.indices[i], o.indices[i] + 1}; break;
        case Representation::Points: v = {std::uint32_t(i)}; break;
    }
    std::vector<float> out;
    for (auto k : v) out.insert(out.end(), o.vertices.begin() + 4 * k, o.vertices.begin() + 4 * k + 4);
    return out;
}

// Field values a G-buffer would sample for primitive i (point fields at its
// vertices, cell fields through its cell).
std::vector<float> fieldsOf(const SceneObject& o, std::size_t i) {
    std::vector<float> out;
    for (const auto& f : o.fields) {
        if (f.association == ScalarField::Association::Cell) {
            out.push_back(f.values[o.primitiveCell.empty() ? i : o.primitiveCell[i]]);
            continue;
        }
        if (o.representation == Representation::Points) {
            out.push_back(f.values[i]);
            continue;
        }
        const std::size_t k = o.representation == Representation::Surface ? 3 : 2;
        for (std::size_t j = 0; j < k; ++j)
            out.push_back(f.values[o.representation == Representation::Surface ? o.indices[3 * i + j] : o.indices[i] + j]);
    }
    return out;
}

const char* kScene =
    "objects:\n"
    "  - file: field.pvtp\n"
    "  - file: field.pvtp\n"
    "    name: dots\n"
    "    representation: points\n"
    "  - generator: streamlines\n"
    "    parameters: {count: 12}\n"
    "  - generator: particles\n"
    "    parameters: {count: 500}\n"
    "cameras:\n"
    "  resolution: [32, 32]\n"
    "  grid: {phi: 3, theta: 2}\n";

void expectSharesMakeTheWhole(int ranks) {
    test::TempDir dir;
    test::writePvtp(dir.path(), "field", test::heightFieldPieces(9, 11, 5));
    const SceneDescription whole = parseSceneFile(kScene, dir.file("scene.yaml"), dir.path());
    const auto shares = onRanks(ranks, [&](ProcessGroup& g) {
        return parseSceneFilePart(kScene, dir.file("scene.yaml"), dir.path(), g);
    });
    const auto& objects = whole.scene->objects;
    // field.pvtp has surface, lines (pieces 1-4) and vertices (piece 4); "dots"
    // restyles those three parts as spheres.
    ASSERT_EQ(objects.size(), 8u);
    for (int r = 0; r < ranks; ++r) {
        const auto& part = shares[std::size_t(r)];
        ASSERT_EQ(part.error, "") << "rank " << r;
        const auto& mine = part.scene.description;
        ASSERT_EQ(mine.scene->objects.size(), objects.size()) << "rank " << r;
        ASSERT_EQ(mine.cameras.size(), whole.cameras.size());
        for (std::size_t c = 0; c < whole.cameras.size(); ++c) {
            EXPECT_EQ(mine.cameras[c].camera.position.x, whole.cameras[c].camera.position.x);
            EXPECT_EQ(mine.cameras[c].camera.position.z, whole.cameras[c].camera.position.z);
        }
        EXPECT_EQ(mine.request.scalars, whole.request.scalars);
    }
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const SceneObject& o = objects[i];
        std::uint64_t next = 0;
        for (int r = 0; r < ranks; ++r) {
            const auto& part = shares[std::size_t(r)].scene;
            const SceneObject& s = part.description.scene->objects[i];
            EXPECT_EQ(s.name, o.name);
            EXPECT_EQ(s.representation, o.representation);
            ASSERT_EQ(s.fields.size(), o.fields.size()) << o.name;
            EXPECT_EQ(part.primitiveOffset[i], next) << o.name << " rank " << r;
            EXPECT_EQ(part.wholePrimitiveCount[i], o.primitiveCount()) << o.name;
            for (std::size_t k = 0; k < s.primitiveCount(); ++k) {
                ASSERT_LT(next + k, o.primitiveCount()) << o.name;
                ASSERT_EQ(primitive(s, k), primitive(o, next + k)) << o.name << " rank " << r << " primitive " << k;
                ASSERT_EQ(fieldsOf(s, k), fieldsOf(o, next + k)) << o.name << " rank " << r << " primitive " << k;
            }
            if (o.representation == Representation::Lines && s.primitiveCount() > 0 && next > 0) {
                EXPECT_NE(o.indices[next], o.indices[next - 1] + 1) << o.name << ": a share starts inside a polyline";
            }
            next += s.primitiveCount();
        }
        EXPECT_EQ(next, o.primitiveCount()) << o.name;
    }
}

}  // namespace

TEST(ScenePartition, SharesOfThreeRanksAddUpToTheWholeScene) { expectSharesMakeTheWhole(3); }
TEST(ScenePartition, OneRankHoldsTheWholeScene) { expectSharesMakeTheWhole(1); }
TEST(ScenePartition, MoreRanksThanPiecesLeavesSomeEmpty) { expectSharesMakeTheWhole(7); }

TEST(ScenePartition, AParallelFileReadWholeAppendsItsPiecesInOrder) {
    test::TempDir dir;
    const auto pieces = test::heightFieldPieces(6, 9, 4);
    const std::string path = test::writePvtp(dir.path(), "f", pieces);
    const auto parts = readMesh(path);
    ASSERT_EQ(parts.size(), 3u);
    EXPECT_EQ(parts[0].name, "f/surface");
    EXPECT_EQ(parts[1].name, "f/lines");
    EXPECT_EQ(parts[2].name, "f/points");
    std::size_t quads = 0, vertices = 0;
    for (const auto& p : pieces) quads += p.polys.size();
    for (const auto& p : pieces) vertices += p.verts.size();
    EXPECT_EQ(parts[0].primitiveCount(), 2 * quads);
    EXPECT_EQ(parts[1].primitiveCount(), 3u * 5u);  // 3 polylines of 6 points
    EXPECT_EQ(parts[2].primitiveCount(), vertices);
    // Cell data follows each piece's cells: the band index of the piece.
    const ScalarField* band = parts[0].field("band");
    ASSERT_TRUE(band);
    EXPECT_EQ(band->values[parts[0].primitiveCell.empty() ? 0 : parts[0].primitiveCell[0]], 0.0f);
    const std::size_t last = parts[0].primitiveCount() - 1;
    EXPECT_EQ(band->values[parts[0].primitiveCell.empty() ? last : parts[0].primitiveCell[last]], 3.0f);
}

TEST(ScenePartition, ABrokenPieceFailsEveryRankNamingTheRankThatReadIt) {
    test::TempDir dir;
    test::writePvtp(dir.path(), "field", test::heightFieldPieces(9, 11, 5));
    // Piece 3 of 5 belongs to rank 1 of 2 (pieces 2..4).
    test::writeText(dir.file("field_3.vtp"), "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"2\"");
    const auto results = onRanks(2, [&](ProcessGroup& g) {
        return parseSceneFilePart(kScene, dir.file("scene.yaml"), dir.path(), g);
    });
    for (const auto& r : results) {
        EXPECT_NE(r.error.find("rank 1: "), std::string::npos) << r.error;
        EXPECT_NE(r.error.find("field_3.vtp"), std::string::npos) << r.error;
    }
    EXPECT_EQ(results[0].error, results[1].error);
}

TEST(ScenePartition, PiecesWithGhostCellsAreRefused) {
    test::TempDir dir;
    const std::string path = test::writePvtp(dir.path(), "g", test::heightFieldPieces(4, 4, 2));
    std::string text = test::readText(path);
    text.replace(text.find("GhostLevel=\"0\""), 14, "GhostLevel=\"1\"");
    test::writeText(path, text);
    try {
        readMesh(path);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("GhostLevel=\"1\""), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("g.pvtp:3:"), std::string::npos) << e.what();
    }
}

TEST(ScenePartition, BlocksCoverEveryItemOnce) {
    for (int size : {1, 2, 3, 7})
        for (std::size_t count : {0u, 1u, 5u, 100u}) {
            std::size_t next = 0;
            for (int r = 0; r < size; ++r) {
                const auto [first, last] = blockOf(count, r, size);
                EXPECT_EQ(first, next);
                EXPECT_LE(first, last);
                next = last;
            }
            EXPECT_EQ(next, count);
        }
}
