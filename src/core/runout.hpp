// Rollers off their shafts (run-out): when the plate loses contact. A tube whose axis sits e off
// its shaft moves its top up and down as e sin(omega t): its downward acceleration reaches
// e omega^2. The plate follows a roller that drops only as fast as gravity brings that end of the
// plate down. With the other roller as a pivot and the centre of mass a distance d from it (d =
// l/2 - x for the plate at x, measured toward the dropping roller; the plate's pitch inertia
// m k^2 about its centre of mass), the end over the dropping roller, l from the pivot, falls at
//
//   a_free = g d l / (k^2 + d^2)
//
// so a roller whose e omega^2 exceeds a_free leaves the plate behind once a turn: it hops. The
// lighter a roller's load (the plate's centre of mass far from it, at the oscillation's turning
// point), the smaller a_free: a plate of amplitude A first hops at d = l/2 - A. Both rollers
// dropping together would need e omega^2 > g. Standard library only.
#pragma once

namespace fl {

// a_free [m/s^2] for a plate of pitch radius of gyration k [m] on rollers l [m] apart whose
// centre of mass is `offset` [m] from the middle, away from the dropping roller (d = l/2 - offset).
double runout_free_fall_acceleration(double spacing, double radius_of_gyration, double gravity,
                                     double offset = 0.0);

// The run-out [m] above which a roller at angular speed omega [rad/s] leaves a plate of amplitude
// A [m] at the turning point: a_free(offset = A) / omega^2.
double runout_hop_threshold(double spacing, double radius_of_gyration, double gravity,
                            double roller_speed, double amplitude = 0.0);

}  // namespace fl
