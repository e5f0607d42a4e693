/// \file OctomapExport.cpp
/// The world as an OctoMap (OctomapExport.h, doc/import-export.md "OctoMap export").

#include <octomap/ColorOcTree.h>
#include <octomap/OcTree.h>
#include <simp/export3d/OctomapExport.h>
#include <simp/obs/Palette.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace simp::export3d {
namespace {

/// MRPT's cell value is the probability of the cell being free; the world's floorplan.png
/// thresholds (world::kWrittenOccupiedThresh, kWrittenFreeThresh) as free probabilities.
constexpr float kWallMaxFree = static_cast<float>(1.0 - world::kWrittenOccupiedThresh);
constexpr float kFreeMinFree = static_cast<float>(1.0 - world::kWrittenFreeThresh);
constexpr std::array<std::uint8_t, 3> kWallColour{160, 160, 160};

enum class Kind { Free, Wall, Object };

/// Voxel centres along one axis covering [lo, hi): the voxel grid is OctoMap's (centres at
/// (k + 0.5) res), so the first centre is the smallest one >= lo.
std::vector<double> centresIn(double lo, double hi, double res) {
    std::vector<double> c;
    for (double v = (std::ceil(lo / res - 0.5) + 0.5) * res; v < hi; v += res) c.push_back(v);
    return c;
}

template <class TREE>
void setVoxel(TREE& tree, double x, double y, double z, Kind kind, const std::array<std::uint8_t, 3>& rgb) {
    octomap::OcTreeKey key;
    if (!tree.coordToKeyChecked(x, y, z, key)) return;  // outside OctoMap's +-3276 m (res 0.1) range
    const float value = kind == Kind::Free ? tree.getClampingThresMinLog() : tree.getClampingThresMaxLog();
    tree.setNodeValue(key, value, /*lazy_eval=*/true);
    if constexpr (std::is_same_v<TREE, octomap::ColorOcTree>)
        if (kind != Kind::Free) tree.setNodeColor(key, rgb[0], rgb[1], rgb[2]);
}

template <class TREE>
void fillCells(TREE& tree, const simp::world::World& w, const OctomapExportOptions& opt, Kind kind,
               OctomapExportSummary& sum) {
    const auto& g = w.floorplan;
    const double r = opt.resolution_m, cell = g.getResolution();
    const auto zs = centresIn(opt.floor_z_m, opt.ceiling_height_m, r);
    for (unsigned cy = 0; cy < g.getSizeY(); ++cy)
        for (unsigned cx = 0; cx < g.getSizeX(); ++cx) {
            const float free_p = g.getCell(cx, cy);
            const bool take = kind == Kind::Wall ? free_p <= kWallMaxFree : free_p >= kFreeMinFree;
            if (!take) continue;
            (kind == Kind::Wall ? sum.wall_cells : sum.free_cells)++;
            const double x0 = g.idx2x(cx) - 0.5 * cell, y0 = g.idx2y(cy) - 0.5 * cell;
            auto xs = centresIn(x0, x0 + cell, r), ys = centresIn(y0, y0 + cell, r);
            // A voxel larger than a cell: the cell still marks the voxel holding its centre.
            if (xs.empty()) xs.push_back(g.idx2x(cx));
            if (ys.empty()) ys.push_back(g.idx2y(cy));
            for (double x : xs)
                for (double y : ys)
                    for (double z : zs) setVoxel(tree, x, y, z, kind, kWallColour);
        }
}

/// Whether a door stands in an open gap: its footprint centre is on a free floor-plan cell.
bool isOpenDoor(const simp::world::World& w, const simp::world::MapObject& o) {
    const auto& g = w.floorplan;
    const int cx = g.x2idx(o.box.center.x()), cy = g.y2idx(o.box.center.y());
    if (cx < 0 || cy < 0 || cx >= static_cast<int>(g.getSizeX()) || cy >= static_cast<int>(g.getSizeY())) return false;
    return g.getCell(cx, cy) > kWallMaxFree;
}

bool isDoor(const simp::world::World& w, const simp::world::MapObject& o, const OctomapExportOptions& opt) {
    return w.objects.class_names.at(static_cast<std::size_t>(o.class_id)) == opt.door_class;
}

template <class TREE>
void fillObjects(TREE& tree, const simp::world::World& w, const OctomapExportOptions& opt, OctomapExportSummary& sum) {
    const double r = opt.resolution_m;
    for (const auto& o : w.objects.objects) {
        if (isDoor(w, o, opt)) {
            if (!opt.export_open_doors && isOpenDoor(w, o)) {
                ++sum.open_doors_skipped;
                continue;
            }
            ++sum.closed_doors;
        }
        ++sum.objects;
        simp::geometry::Box3D grown = o.box;  // within half a voxel of the box
        grown.size += Eigen::Vector3d::Constant(r);
        Eigen::Vector3d lo = grown.center, hi = grown.center;
        for (const auto& c : grown.corners()) {
            lo = lo.cwiseMin(c);
            hi = hi.cwiseMax(c);
        }
        const auto rgb = simp::obs::classColorRgb(o.class_id, w.objects.class_names);
        for (double x : centresIn(lo.x(), hi.x(), r))
            for (double y : centresIn(lo.y(), hi.y(), r))
                for (double z : centresIn(lo.z(), hi.z(), r))
                    if (simp::geometry::containsPoint(grown, {x, y, z})) setVoxel(tree, x, y, z, Kind::Object, rgb);
    }
}

template <class TREE>
OctomapExportSummary build(TREE& tree, const simp::world::World& w, const OctomapExportOptions& opt) {
    OctomapExportSummary sum;
    if (opt.mark_free_space) fillCells(tree, w, opt, Kind::Free, sum);  // first: walls and boxes overwrite
    fillCells(tree, w, opt, Kind::Wall, sum);
    fillObjects(tree, w, opt, sum);
    tree.updateInnerOccupancy();
    tree.prune();
    for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it)
        (tree.isNodeOccupied(*it) ? sum.occupied_leaves : sum.free_leaves)++;
    return sum;
}

std::string lowerExtension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

}  // namespace

double estimateVoxels(const simp::world::World& w, const OctomapExportOptions& opt) {
    const auto& g = w.floorplan;
    const double r = opt.resolution_m;
    const double per_cell_xy = std::max(1.0, std::pow(g.getResolution() / r, 2));
    const double layers = std::ceil((opt.ceiling_height_m - opt.floor_z_m) / r);
    double cells = 0;
    for (unsigned cy = 0; cy < g.getSizeY(); ++cy)
        for (unsigned cx = 0; cx < g.getSizeX(); ++cx) {
            const float f = g.getCell(cx, cy);
            if (f <= kWallMaxFree || (opt.mark_free_space && f >= kFreeMinFree)) ++cells;
        }
    double boxes = 0;
    for (const auto& o : w.objects.objects) boxes += (o.box.size + Eigen::Vector3d::Constant(r)).prod() / (r * r * r);
    return cells * per_cell_xy * layers + boxes;
}

OctomapExportSummary writeWorldOctomap(const simp::world::World& w, const OctomapExportOptions& opt,
                                       const std::string& path) {
    opt.validate("octomap export options:");
    const std::string ext = lowerExtension(path);
    if (ext != ".bt" && ext != ".ot")
        throw std::invalid_argument(path + ": the OctoMap file must end in .bt (OcTree, binary) or .ot (ColorOcTree)");
    const double estimate = estimateVoxels(w, opt);
    if (estimate > opt.max_voxels)
        throw std::invalid_argument(path + ": about " + std::to_string(static_cast<long long>(estimate)) +
                                    " voxels at resolution_m = " + std::to_string(opt.resolution_m) +
                                    " m exceed max_voxels = " + std::to_string(static_cast<long long>(opt.max_voxels)) +
                                    " ([octomap] keys): use a coarser resolution or raise max_voxels");
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    OctomapExportSummary sum;
    bool ok = false;
    if (ext == ".bt") {
        octomap::OcTree tree(opt.resolution_m);
        sum = build(tree, w, opt);
        ok = tree.writeBinary(path);
    } else {
        octomap::ColorOcTree tree(opt.resolution_m);
        sum = build(tree, w, opt);
        ok = tree.write(path);
    }
    if (!ok) throw std::runtime_error(path + ": cannot be written (OctoMap)");
    sum.estimated_voxels = estimate;
    sum.bytes = static_cast<std::size_t>(std::filesystem::file_size(path));
    return sum;
}

mrpt::maps::COctoMap toMrptOctoMap(const std::string& path, double max_voxels) {
    std::unique_ptr<octomap::AbstractOcTree> tree;
    if (lowerExtension(path) == ".bt") {
        auto t = std::make_unique<octomap::OcTree>(0.1);
        if (t->readBinary(path)) tree = std::move(t);
    } else {
        tree.reset(octomap::AbstractOcTree::read(path));
    }
    auto* occ = dynamic_cast<octomap::OccupancyOcTreeBase<octomap::OcTreeNode>*>(tree.get());
    const auto* col = dynamic_cast<octomap::ColorOcTree*>(tree.get());
    if (!occ && !col) throw std::invalid_argument(path + ": not an OctoMap .bt / .ot occupancy tree");
    const double res = tree->getResolution();
    mrpt::maps::COctoMap map(res);
    double voxels = 0;
    const auto add = [&](const octomap::point3d& c, double size, bool occupied) {
        const int n = std::max(1, static_cast<int>(std::lround(size / res)));
        voxels += static_cast<double>(n) * n * n;
        if (voxels > max_voxels)
            throw std::invalid_argument(path + ": more than " + std::to_string(static_cast<long long>(max_voxels)) +
                                        " voxels for an MRPT COctoMap");
        const double first = -0.5 * size + 0.5 * res;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k)
                    map.updateVoxel(c.x() + first + i * res, c.y() + first + j * res, c.z() + first + k * res, occupied);
    };
    if (col) {
        for (auto it = col->begin_leafs(), end = col->end_leafs(); it != end; ++it)
            add(it.getCoordinate(), it.getSize(), col->isNodeOccupied(*it));
    } else {
        for (auto it = occ->begin_leafs(), end = occ->end_leafs(); it != end; ++it)
            add(it.getCoordinate(), it.getSize(), occ->isNodeOccupied(*it));
    }
    return map;
}

std::string exportOctomapCommand(const simp::world::World& world, const std::string& ini_path,
                                 const std::string& resolution_text, const std::string& path) {
    OctomapExportOptions opt = ini_path.empty() ? OctomapExportOptions{} : loadOctomapExportOptions(ini_path);
    if (!resolution_text.empty()) {
        std::size_t used = 0;
        double r = 0;
        try {
            r = std::stod(resolution_text, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != resolution_text.size() || !std::isfinite(r))
            throw std::invalid_argument("option --resolution: '" + resolution_text + "' is not a number (m)");
        opt.resolution_m = r;
        opt.validate("option --resolution:");
    }
    std::cerr << "simp-export-map: building the OctoMap of about "
              << static_cast<long long>(estimateVoxels(world, opt)) << " voxels at " << opt.resolution_m
              << " m ...\n";  // progress: several seconds for an office at 0.05 m
    const auto s = writeWorldOctomap(world, opt, path);
    std::ostringstream out;
    out << "Wrote the 3D map as OctoMap " << path << " (" << s.bytes << " bytes): resolution " << opt.resolution_m
        << " m, walls " << s.wall_cells << " floor-plan cells extruded " << opt.floor_z_m << " .. "
        << opt.ceiling_height_m << " m, " << s.objects << " object boxes (" << s.closed_doors << " closed doors, "
        << s.open_doors_skipped << " open doors left out), " << s.free_cells << " free cells; "
        << static_cast<long long>(s.estimated_voxels) << " voxels estimated (checked against max_voxels), "
        << s.occupied_leaves << " occupied and " << s.free_leaves << " free leaves after pruning\n";
    return out.str();
}

}  // namespace simp::export3d
