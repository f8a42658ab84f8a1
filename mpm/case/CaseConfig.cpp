#include "case/CaseConfig.hpp"

#include <sstream>

#include "core/Error.hpp"

namespace qs {

const MaterialConfig& CaseConfig::material(const std::string& name) const {
    for (const MaterialConfig& m : materials)
        if (m.name == name) return m;
    std::ostringstream s;
    s << "no material named '" << name << "' in [materials]; defined:";
    if (materials.empty()) s << " none";
    for (const MaterialConfig& m : materials) s << " '" << m.name << "'";
    throw Error(s.str());
}

double CaseConfig::sandTop() const {
    double z = column.chamberHeight;  // the filter
    for (const LayerConfig& layer : layers) z += layer.thickness;
    return z;
}

}  // namespace qs
