#pragma once
// An electrode's voltage waveform as a case file gives it (its kind and shape keys), and the g(t)
// it makes (docs/electrostatics.md §1): kept so that a sweep or an optimisation can set a shape key
// and the waveform is built again.

#include "model/time_function.hpp"

namespace vi {

// V(t) = voltage g(t). constant: g = 1. step: 0 before t_on, 1 after. ramp: 0 to 1 over rise from
// t_on. pulse: up over rise, held for hold, down over fall. two_step: up to level over rise, held
// for hold, up (or down) to 1 over rise. sine: V = bias + voltage sin(2 pi frequency t + phase).
// table: volts from a CSV file (g in the electrode's TimeFunction). given: g set directly in the
// electrode's TimeFunction by code, with no shape keys.
struct Waveform {
    enum class Kind { given, constant, step, ramp, pulse, two_step, sine, table };
    Kind kind = Kind::given;
    double t_on = 0.0;       // start [s]
    double rise = 0.0;       // each edge's duration of ramp, pulse, two_step [s]
    double hold = 0.0;       // pulse: at full voltage; two_step: at the first level [s]
    double fall = 0.0;       // pulse: the falling edge [s]
    double level = 0.0;      // two_step: the first level as a fraction of the voltage [-]
    double frequency = 0.0;  // sine [Hz]
    double phase = 0.0;      // sine [rad]
    double bias = 0.0;       // sine: the mean voltage [V]
};

// The case file's name of a kind ("two_step").
const char* waveform_name(Waveform::Kind k);

// True for the kinds whose g(t) waveform_function builds (not given, not table).
bool built_from_shape(Waveform::Kind k);

// g(t) of w for the amplitude `voltage` (the sine's bias is volts: its offset is bias / voltage, 0
// when voltage is 0). Ramps, pulses and two-step drives are piecewise linear, so they become tables:
// every solver already integrates those exactly between knots and stops at each knot. Values the
// case checks refuse (a rise not above 0) give a g(t) that is never run. Only for built_from_shape.
TimeFunction waveform_function(const Waveform& w, double voltage);

}  // namespace vi
