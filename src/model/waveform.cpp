#include "model/waveform.hpp"

namespace vi {

const char* waveform_name(Waveform::Kind k) {
    switch (k) {
        case Waveform::Kind::given: return "given";
        case Waveform::Kind::constant: return "constant";
        case Waveform::Kind::step: return "step";
        case Waveform::Kind::ramp: return "ramp";
        case Waveform::Kind::pulse: return "pulse";
        case Waveform::Kind::two_step: return "two_step";
        case Waveform::Kind::sine: return "sine";
        case Waveform::Kind::table: return "table";
    }
    return "?";
}

bool built_from_shape(Waveform::Kind k) { return k != Waveform::Kind::given && k != Waveform::Kind::table; }

TimeFunction waveform_function(const Waveform& w, double voltage) {
    using Kind = TimeFunction::Kind;
    TimeFunction g;
    switch (w.kind) {
        case Waveform::Kind::given:
        case Waveform::Kind::table:
        case Waveform::Kind::constant: break;
        case Waveform::Kind::step:
            g.kind = Kind::step;
            g.t_on = w.t_on;
            break;
        case Waveform::Kind::ramp:
            g.kind = Kind::table;
            g.times = {w.t_on, w.t_on + w.rise};
            g.values = {0.0, 1.0};
            break;
        case Waveform::Kind::pulse:
            g.kind = Kind::table;
            g.times = {w.t_on, w.t_on + w.rise, w.t_on + w.rise + w.hold, w.t_on + w.rise + w.hold + w.fall};
            g.values = {0.0, 1.0, 1.0, 0.0};
            break;
        case Waveform::Kind::two_step:
            g.kind = Kind::table;
            g.times = {w.t_on, w.t_on + w.rise, w.t_on + w.rise + w.hold, w.t_on + 2.0 * w.rise + w.hold};
            g.values = {0.0, w.level, w.level, 1.0};
            break;
        case Waveform::Kind::sine:
            g.kind = Kind::harmonic;
            g.frequency_hz = w.frequency;
            g.phase = w.phase;
            g.offset = voltage != 0.0 ? w.bias / voltage : 0.0;
            break;
    }
    return g;
}

}  // namespace vi
