#include "problem/element_families.hpp"

#include "model/case_schema.hpp"

#include "forces/hertz_contact.hpp"
#include "forces/intrinsic_curvature.hpp"
#include "forces/midplane_stretching.hpp"
#include "forces/point_load_element.hpp"
#include "forces/support_contacts.hpp"
#include "problem/buckling_check.hpp"
#include "problem/electrode_elements.hpp"
#include "problem/film_elements.hpp"

namespace vi {

// A new kind of force element adds its family here (and its header above).
const std::vector<const ElementFamily*>& element_families() {
    static const std::vector<const ElementFamily*> families{
        &support_contacts(),   // [[supports]]: plain or adhesive contacts
        &hertz_contacts(),     // [[supports]] with law = "hertz"
        &point_loads(),        // [[loads]]
        &electrode_pads(),     // [[electrodes]]: the electrostatic force
        &dielectric_layers(),  // [[electrodes]] with a dielectric layer: contacts
        &squeeze_films(),      // [air]: the electrodes' films and [[films]]
        &beam_stretching(),    // beam.stretching
        &intrinsic_curvatures(),  // [curl]: the released beam's curvature
    };
    return families;
}

namespace {

// Every family's own keys, registered before the first case is read, and the rules that need the
// finite-element model (a beam of sections buckles at its own Euler load).
const bool kFamilyKeysRegistered = register_at_first_use([] {
    for (const ElementFamily* family : element_families()) family->register_case_keys();
    add_section_check("beam.sections", check_sectioned_buckling);
});

}  // namespace

}  // namespace vi
