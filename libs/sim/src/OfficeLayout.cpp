#include <simp/sim/OfficeLayout.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace simp::sim {
namespace {

double snap(double v, double res) { return std::round(v / res) * res; }

/// Room widths along one row, snapped to the grid.
std::vector<double> drawWidths(int count, const OfficeParams& p, Rng& rng) {
    std::vector<double> w(static_cast<std::size_t>(count));
    for (auto& x : w) x = snap(rng.uniform(p.room_width_min_m, p.room_width_max_m), p.resolution_m);
    return w;
}

void placeRow(const std::vector<double>& widths, double x_start, double row_length, double y0, double y1,
              double door_side, const OfficeParams& p, Rng& rng, std::vector<Room>& out) {
    const double t = p.wall_thickness_m;
    double x = x_start;
    for (std::size_t i = 0; i < widths.size(); ++i) {
        Room r;
        const bool last = i + 1 == widths.size();
        const double x1 = last ? x_start + row_length : x + widths[i];
        r.interior = {x, y0, x1, y1};
        const double margin = 0.3 + p.door_width_m / 2;
        const double c = snap(rng.uniform(x + margin, x1 - margin), p.resolution_m);
        if (door_side > 0)
            r.door_gap = {c - p.door_width_m / 2, y1, c + p.door_width_m / 2, y1 + t};
        else
            r.door_gap = {c - p.door_width_m / 2, y0 - t, c + p.door_width_m / 2, y0};
        r.door_side_y = door_side;
        out.push_back(r);
        x = x1 + t;
    }
}

double rowLength(const std::vector<double>& w, double t) {
    if (w.empty()) return 0;
    double s = 0;
    for (double x : w) s += x;
    return s + t * static_cast<double>(w.size() - 1);
}

void assignRoomTypes(std::vector<Room>& rooms, const OfficeParams& p, Rng& rng) {
    const std::size_t n = rooms.size();
    std::vector<std::size_t> free_idx;
    for (std::size_t i = 0; i < n; ++i) {
        rooms[i].type = RoomType::Office;
        free_idx.push_back(i);
    }
    if (n >= 3) {  // the first room (near the entrance corner) is the reception
        rooms[0].type = RoomType::Reception;
        free_idx.erase(free_idx.begin());
    }
    const auto take = [&](RoomType type) {
        const std::size_t k = rng.index(free_idx.size());
        rooms[free_idx[k]].type = type;
        free_idx.erase(free_idx.begin() + static_cast<std::ptrdiff_t>(k));
    };
    if (n >= 4) {
        const int kitchens = std::max(1, static_cast<int>(std::lround(static_cast<double>(n) / p.kitchen_every_n_rooms)));
        for (int k = 0; k < kitchens && !free_idx.empty(); ++k) take(RoomType::Kitchen);
    }
    const int meetings = static_cast<int>(std::lround(p.meeting_fraction * static_cast<double>(free_idx.size())));
    for (int k = 0; k < meetings && free_idx.size() > 1; ++k) take(RoomType::Meeting);
}

}  // namespace

const char* roomTypeName(RoomType t) {
    switch (t) {
        case RoomType::Office: return "office";
        case RoomType::Meeting: return "meeting";
        case RoomType::Kitchen: return "kitchen";
        case RoomType::Reception: return "reception";
        case RoomType::Corridor: return "corridor";
    }
    return "?";
}

OfficeLayout makeOfficeLayout(const OfficeParams& p, Rng& rng) {
    p.validate();
    const double t = snap(p.wall_thickness_m, p.resolution_m);
    const double wc = snap(p.corridor_width_m, p.resolution_m);
    int n = p.rooms;
    if (p.size_m2 > 0) {
        const double w = 0.5 * (p.room_width_min_m + p.room_width_max_m) + t;
        const double d = 0.5 * (p.room_depth_min_m + p.room_depth_max_m) + t + 0.5 * (wc + t);
        n = std::max(1, static_cast<int>(std::lround(p.size_m2 / (w * d))));
    }
    const int per_band = 2 * p.max_rooms_per_side;
    const int bands = (n + per_band - 1) / per_band;
    const double x_rooms = bands > 1 ? 2 * t + wc : t;

    OfficeLayout L;
    std::vector<Room> corridors;
    double y = t, x_max = x_rooms;
    int left = n;
    double first_corr_y0 = 0, last_corr_y1 = 0;
    for (int b = 0; b < bands; ++b) {
        const int nb = std::min(left, (left + (bands - b) - 1) / (bands - b));
        left -= nb;
        const auto w_low = drawWidths((nb + 1) / 2, p, rng);
        const auto w_up = drawWidths(nb / 2, p, rng);
        const double len = std::max(rowLength(w_low, t), rowLength(w_up, t));
        const double d_low = snap(rng.uniform(p.room_depth_min_m, p.room_depth_max_m), p.resolution_m);
        const double d_up = snap(rng.uniform(p.room_depth_min_m, p.room_depth_max_m), p.resolution_m);
        const double corr_y0 = y + d_low + t, corr_y1 = corr_y0 + wc;
        placeRow(w_low, x_rooms, len, y, y + d_low, +1, p, rng, L.rooms);
        Room corr;
        corr.type = RoomType::Corridor;
        corr.interior = {t, corr_y0, x_rooms + len, corr_y1};
        corridors.push_back(corr);
        if (b == 0) first_corr_y0 = corr_y0;
        last_corr_y1 = corr_y1;
        if (!w_up.empty()) {
            placeRow(w_up, x_rooms, len, corr_y1 + t, corr_y1 + t + d_up, -1, p, rng, L.rooms);
            y = corr_y1 + 2 * t + d_up;
        } else {
            y = corr_y1 + t;
        }
        x_max = std::max(x_max, x_rooms + len);
    }
    if (bands > 1) {
        Room conn;
        conn.type = RoomType::Corridor;
        conn.interior = {t, first_corr_y0, t + wc, last_corr_y1};
        corridors.push_back(conn);
    }
    assignRoomTypes(L.rooms, p, rng);
    for (auto& c : corridors) L.rooms.push_back(c);
    for (std::size_t i = 0; i < L.rooms.size(); ++i) L.rooms[i].id = static_cast<int>(i) + 1;
    L.bounds = {0, 0, x_max + t, y};
    return L;
}

namespace {
/// Inclusive cell index range whose cell centres lie inside r; empty when lo > hi.
void cellRange(const mrpt::maps::COccupancyGridMap2D& grid, const Rect& r, int& cx0, int& cx1, int& cy0, int& cy1) {
    const int nx = static_cast<int>(grid.getSizeX()), ny = static_cast<int>(grid.getSizeY());
    const double res = grid.getResolution();
    cx0 = std::max(0, static_cast<int>(std::ceil((r.x0 - grid.getXMin()) / res - 0.5)));
    cx1 = std::min(nx - 1, static_cast<int>(std::floor((r.x1 - grid.getXMin()) / res - 0.5)));
    cy0 = std::max(0, static_cast<int>(std::ceil((r.y0 - grid.getYMin()) / res - 0.5)));
    cy1 = std::min(ny - 1, static_cast<int>(std::floor((r.y1 - grid.getYMin()) / res - 0.5)));
}
}  // namespace

void fillRect(mrpt::maps::COccupancyGridMap2D& grid, const Rect& r, bool occupied) {
    int cx0, cx1, cy0, cy1;
    cellRange(grid, r, cx0, cx1, cy0, cy1);
    for (int cy = cy0; cy <= cy1; ++cy)
        for (int cx = cx0; cx <= cx1; ++cx) grid.setCell(cx, cy, occupied ? 0.0f : 1.0f);
}

void rasterizeLayout(const OfficeLayout& layout, double res, mrpt::maps::COccupancyGridMap2D& grid,
                     world::RoomMap& rooms) {
    const double margin = 1.0;
    grid.setSize(layout.bounds.x0 - margin, layout.bounds.x1 + margin, layout.bounds.y0 - margin,
                 layout.bounds.y1 + margin, res, 0.5f);
    fillRect(grid, layout.bounds, true);
    for (const auto& r : layout.rooms) fillRect(grid, r.interior, false);
    for (const auto& r : layout.rooms)
        if (r.door_gap.area() > 0) fillRect(grid, r.door_gap, false);

    const int nx = static_cast<int>(grid.getSizeX()), ny = static_cast<int>(grid.getSizeY());
    rooms.resolution_m = res;
    rooms.origin_x_m = grid.getXMin();
    rooms.origin_y_m = grid.getYMin();
    rooms.ids = cv::Mat1w(ny, nx, static_cast<std::uint16_t>(0));
    for (const auto& r : layout.rooms) {
        int cx0, cx1, cy0, cy1;
        cellRange(grid, r.interior, cx0, cx1, cy0, cy1);
        for (int cy = cy0; cy <= cy1; ++cy)
            for (int cx = cx0; cx <= cx1; ++cx) rooms.ids(ny - 1 - cy, cx) = static_cast<std::uint16_t>(r.id);
    }
}

}  // namespace simp::sim
