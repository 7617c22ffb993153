// The work-precision study ("error against run time"): the minimal physics of a scene run over a
// grid of time steps and solver iterations; for each, the period error against the thick-plate
// formula, the amplitude drift per period and the wall time per simulated second; and the error
// law fitted to the results.
#pragma once

#include <optional>
#include <vector>

#include "lab/run/job_control.hpp"
#include "scene/scene.hpp"

namespace fl {

struct AccuracyPoint {
  double time_step = 0.0;  // s
  int solver_iterations = 0;
  double period = 0.0;                     // s, from the trajectory
  double period_error = 0.0;               // relative, against the thick formula
  double predicted_error = 0.0;            // -(omega dt)^2 / 24
  double amplitude_drift = 0.0;            // relative per period
  double wall_per_simulated_second = 0.0;  // s
  bool valid = false;                      // enough crossings to measure a period
};

// err = -coefficient (omega dt)^exponent, fitted in log-log over the points whose error is above
// the floor set by the solver and the run's length.
struct ErrorLaw {
  double coefficient = 0.0;
  double exponent = 0.0;
  int points = 0;
};

struct AccuracyStudy {
  double period_thick = 0.0;  // s
  double omega = 0.0;         // rad/s
  std::vector<AccuracyPoint> points;
  std::optional<ErrorLaw> law;
  bool interrupted = false;  // asked to stop: `points` are those finished, the grid's order
};

struct AccuracyGrid {
  std::vector<double> time_steps{1.0 / 120,  1.0 / 240,  1.0 / 500,  1.0 / 1000,
                                 1.0 / 2000, 1.0 / 5000, 1.0 / 10000};
  std::vector<int> solver_iterations{5, 10, 20, 50};
  int periods = 10;  // simulated per point
};

// Asked to stop (control), it keeps the points finished and drops the one it was running.
AccuracyStudy run_accuracy_study(const Scene& scene, const AccuracyGrid& grid,
                                 const JobControl& control = {});

// Fits the error law to the points with the most solver iterations at each step whose |error| is
// above `floor`; nullopt with fewer than 3 such points.
std::optional<ErrorLaw> fit_error_law(const std::vector<AccuracyPoint>& points, double omega,
                                      double floor = 1e-9);

}  // namespace fl
