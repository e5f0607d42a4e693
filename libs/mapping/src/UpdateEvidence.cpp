/// \file UpdateEvidence.cpp
/// The per-object evidence file of a map update (UpdateEvidence.h).
#include <simp/mapping/UpdateEvidence.h>

#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace simp::mapping {

void saveUpdateEvidence(const std::vector<UpdateEvidence>& rows, const std::string& path) {
    std::ofstream f(path);
    if (!f) throw std::runtime_error("cannot write '" + path + "'");
    f << "id\torigin\tclass\tx_m\ty_m\twindows_matched\twindows_missed\twindows_expected\twindows_missed_behind_new\tclass_rate\tp_present"
         "\tdecision\tnearest_id\tnearest_m\tnearest_windows\tturn_deg\tturn_std_error_deg\tturn_concentration\n";
    f << std::fixed;
    for (const UpdateEvidence& r : rows)
        f << r.id << '\t' << r.origin << '\t' << r.class_name << '\t' << std::setprecision(3) << r.x_m << '\t' << r.y_m
          << '\t' << r.windows_matched << '\t' << r.windows_missed << '\t' << r.windows_matched + r.windows_missed
          << '\t' << r.windows_missed_behind_new << '\t' << std::setprecision(3) << r.class_rate << '\t' << std::setprecision(6) << r.p_present << '\t'
          << r.decision << '\t' << r.nearest_id << '\t' << std::setprecision(3) << r.nearest_m << '\t'
          << r.nearest_windows << '\t' << std::setprecision(1) << r.turn_deg << '\t' << r.turn_std_error_deg << '\t'
          << std::setprecision(3) << r.turn_concentration << '\n';
    if (!f) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace simp::mapping
