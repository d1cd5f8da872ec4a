#include "io/air_reader.hpp"

namespace vi {

using tomlio::FieldReader;

Air read_air(const toml::table& t, tomlio::Position at, tomlio::ReadLog& log) {
    FieldReader f(t, "air", at, log, {"pressure", "temperature", "viscosity", "mean_free_path", "film"});
    Air a;
    if (auto v = f.quantity("pressure", Dimension::pressure, false)) a.pressure = *v;
    if (auto v = f.quantity("temperature", Dimension::temperature, false)) a.temperature = *v;
    if (auto v = f.quantity("viscosity", Dimension::viscosity, false)) a.viscosity = *v;
    if (auto v = f.quantity("mean_free_path", Dimension::length, false)) a.mean_free_path = *v;
    if (auto v = f.boolean("film", false)) a.film = *v;
    f.finish();
    return a;
}

Film read_film(const toml::table& t, const std::string& path, tomlio::Position at, tomlio::ReadLog& log) {
    FieldReader f(t, path, at, log, {"from", "to", "side", "gap"});
    Film m;
    if (auto v = f.quantity("from", Dimension::dimensionless, true)) m.from = *v;
    if (auto v = f.quantity("to", Dimension::dimensionless, true)) m.to = *v;
    if (auto v = f.choice("side", {"below", "above"}, false)) m.side = (*v == "above") ? Side::above : Side::below;
    if (auto v = f.quantity("gap", Dimension::length, true)) m.gap = *v;
    f.finish();
    return m;
}

}  // namespace vi
