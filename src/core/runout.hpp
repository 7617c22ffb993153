// Rollers off their shafts (run-out): when the plate loses contact. A tube whose axis sits e off
// its shaft moves its top up and down as -e sin(phi + theta), theta the roller's angle: its upward
// acceleration is a = e omega^2 sin(phi + theta), down to -e omega^2 once a turn.
//
// One roller off its shaft, the other true: the plate follows the dropping roller only as fast as
// gravity brings that end down. With the true roller as a pivot and the centre of mass a distance d
// from it (the plate's pitch inertia m k^2 about its centre of mass), the end over the dropping
// roller, l from the pivot, falls at
//
//   a_free = g d l / (k^2 + d^2)
//
// so a roller whose e omega^2 exceeds a_free leaves the plate behind once a turn: it hops.
//
// Both rollers off (the same e, phases phi0 and phi1): a plate resting on both tops has its heave
// and pitch set by them, and Newton's laws for both give the load on roller 1, its centre of mass
// d from roller 0,
//
//   N1 = (m / l') (d' g + B a0 + A a1),   A = (k^2 + d' d) / l,  B = d' - A,
//
// where the kinetic friction mu_k N_i at the contacts, h_c below the centre of mass, adds its
// torque: d' = d - mu_k h_c, l' = l - 2 mu_k h_c (the thick plate's load shift; with a0 = a1 = 0,
// N1 = m g d' / l').
//
// The rollers turn opposite ways (theta1 = -theta0), so over a turn B a0 + A a1 swings between
// +-e omega^2 R with R^2 = A^2 + B^2 - 2 A B cos(phi0 + phi1): the plate keeps roller 1 while
// e omega^2 R <= d' g, its least load N1 = (m g d' / l') (1 - e / e*) below the threshold e*.
// Tubes half a turn apart in that sum (phi0 + phi1 = pi) heave the plate without pitching it
// (R = d'): it leaves them at e omega^2 = g. The lighter a roller's load (the
// plate's centre of mass far from it, at the oscillation's turning point), the smaller d: a plate
// of amplitude A first hops at d = l/2 - A, by symmetry at either roller. Standard library only.
#pragma once

namespace fl {

// a_free [m/s^2] for a plate of pitch radius of gyration k [m] on rollers l [m] apart, one of them
// true, whose centre of mass is `offset` [m] from the middle, away from the dropping roller
// (d = l/2 - offset).
double runout_free_fall_acceleration(double spacing, double radius_of_gyration, double gravity,
                                     double offset = 0.0);

// The run-out e* [m] above which rollers at angular speed omega [rad/s], both e off their shafts
// with phases summing to `phase_sum` [rad], leave a plate of amplitude A [m] at its turning points:
// d' g / (omega^2 R) with d = l/2 - A. `friction_lever` is mu_k h_c [m] (0 for a thin plate).
double runout_hop_threshold(double spacing, double radius_of_gyration, double gravity,
                            double roller_speed, double phase_sum, double amplitude = 0.0,
                            double friction_lever = 0.0);

}  // namespace fl
