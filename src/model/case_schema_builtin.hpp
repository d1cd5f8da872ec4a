#pragma once
// The built-in sections of the case-file schema, one maker per section (model/case_keys_*.cpp).

#include "model/case_schema.hpp"

namespace vi::schema {

SectionSpec top_level_section();
SectionSpec beam_section();
SectionSpec material_section();
SectionSpec beam_sections_section();
SectionSpec materials_section();
SectionSpec supports_section();
SectionSpec damping_section();
SectionSpec initial_section();
SectionSpec loads_section();
SectionSpec electrodes_section();
SectionSpec air_section();
SectionSpec films_section();
SectionSpec solver_section();

}  // namespace vi::schema
