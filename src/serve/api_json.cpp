#include "serve/api_json.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/units.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"
#include "lab/request/field_checks.hpp"
#include "serve/web_spelling.hpp"
#include "text/describe.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;

json vec3(const Vec3& v) {
  return json::array({v[0], v[1], v[2]});
}

json paper_json(const CompiledRig& rig, const PaperTable& table) {
  const FrictionSource& source = rig.friction_source;
  if (!source.paper_material || !source.paper_period || !source.paper_mu_k) return nullptr;
  const PaperMaterial* row = table.find(*source.paper_material);
  return {{"material", row != nullptr ? row->name : *source.paper_material},
          {"key", *source.paper_material},
          {"temperature_k", source.temperature},
          {"period", source.paper_period->value},
          {"period_err", source.paper_period->uncertainty},
          {"mu_k", source.paper_mu_k->value},
          {"mu_k_err", source.paper_mu_k->uncertainty}};
}

}  // namespace

json lab_json(const std::vector<SceneEntry>& scenes, const PaperTable& table,
              const std::string& version) {
  json out{{"scenes", json::array()}, {"materials", json::array()}, {"version", version}};
  for (const SceneEntry& s : scenes)
    out["scenes"].push_back({{"name", s.name}, {"title", s.title}});
  for (const PaperMaterial& m : table.materials) {
    json temperatures = json::array({m.room.temperature});
    if (m.cold) temperatures.push_back(m.cold->temperature);
    out["materials"].push_back(
        {{"key", m.key}, {"name", m.name}, {"temperatures_k", temperatures}});
  }
  return out;
}

json rig_json(const std::string& scene, const CompiledRig& rig,
              const std::vector<AcceptedRange>& accepts, const PaperTable& table) {
  const PlateDesc& p = rig.plate_desc;
  json ranges = json::array();
  for (const AcceptedRange& r : accepts)
    ranges.push_back({{"key", r.key}, {"least", r.least}, {"most", r.most}, {"unit", r.unit}});
  json blocks = json::array();
  for (const PlateBlock& b : p.blocks)
    blocks.push_back({{"part", b.part}, {"x", b.x}, {"y", b.y}, {"turn_deg", b.turn}});
  json magnets = json::array();
  for (const MagnetDesc& m : rig.magnets)
    magnets.push_back(
        {{"x", m.x}, {"height", m.height}, {"diameter", m.diameter}, {"thickness", m.thickness}});
  json frame = json::array();
  if (rig.frame)
    for (const FramePart& part : rig.frame->parts)
      frame.push_back({{"part", part.part},
                       {"position", vec3(part.position)},
                       {"turn_deg", part.turn},
                       {"color", json::array({part.color[0], part.color[1], part.color[2]})}});
  json sensor = nullptr;
  if (rig.sensor)
    sensor = {{"x", rig.sensor->position[0]},
              {"y", rig.sensor->position[1]},
              {"z", rig.sensor->position[2]}};
  return {
      {"scene", scene},
      {"spacing", rig.rollers.spacing},
      {"roller_radius", rig.rollers.radius},
      {"roller_length", rig.rollers.length},
      {"roller_sense", rig.rollers.sense == RollerSense::kInward ? "inward" : "outward"},
      {"roller_speed_rpm", rig.roller_speed_nominal * kRpmPerRadPerSecond},
      {"drive", rig.drive.has_value()},
      {"motor_duty", rig.drive ? json(rig.drive->parts.motor.duty) : json(nullptr)},
      {"runout", rig.rollers.runout},
      {"plate",
       {{"length", p.length},
        {"width", p.width},
        {"thickness", p.thickness},
        {"mass", rig.plate.mass},
        {"h_c", rig.plate.h_c},
        {"material", p.material},
        {"blocks", blocks}}},
      {"magnets", magnets},
      {"sensor", sensor},
      {"frame", frame},
      {"offset", p.offset},
      {"duration", rig.world.duration},
      {"time_step", rig.world.time_step},
      {"seed", rig.world.seed},
      {"gravity", rig.world.gravity},
      {"friction_law", rig.friction.depends_on_slip() ? "slip-dependent" : "coulomb"},
      {"mu_k", rig.friction.mu_k},
      {"temperature_k", rig.friction_source.temperature},
      {"period_thin", rig.period_thin},
      {"period_thick", json_or_null(rig.period_thick)},
      {"omega", json_or_null(rig.omega)},
      {"tipping_amplitude", json_or_null(rig.tipping_amplitude)},
      {"paper", paper_json(rig, table)},
      {"accepts", ranges},
  };
}

json estimate_json(const std::optional<EstimatorReport>& report) {
  if (!report || report->periods_used == 0) return nullptr;
  // The spreads and mu_k's uncertainty from two periods on, as the summary gives them: one
  // period has none (null, never 0).
  const EstimatorReport& e = *report;
  const bool spread = e.has_spread();
  const auto measured = [spread](double v) { return spread ? json(v) : json(nullptr); };
  return {{"periods_used", e.periods_used},
          {"periods_discarded", e.periods_discarded},
          {"pulses", e.pulses},
          {"period", e.period},
          {"period_sd", measured(e.period_std)},
          {"period_se", measured(e.period_std_error)},
          {"mu_k", e.mu_k},
          {"mu_k_err", measured(e.mu_k_err_quadrature)},
          {"mu_k_err_worst", measured(e.mu_k_err_worst)}};
}

json periods_json(const std::vector<EstimatedPeriod>& periods, std::size_t from) {
  json out = json::array();
  for (std::size_t i = from; i < periods.size(); ++i) {
    const EstimatedPeriod& p = periods[i];
    out.push_back(json::array({p.start, p.end, p.period, p.status == fl_estimator::kAccepted}));
  }
  return out;
}

json frame_json(const LiveFrame& f, bool playing, double speed) {
  json hall = json::array();
  for (const HallSample& s : f.hall)
    hall.push_back(json::array({static_cast<double>(s.t_us) * 1e-6, s.adc}));
  return {
      {"t", f.t},
      {"x", f.plate.x},
      {"x_theory", json_or_null(f.x_theory)},
      {"y", f.plate.y},
      {"z", f.plate.z},
      {"pitch", f.plate.pitch},
      {"yaw", f.plate.yaw},
      {"vx", f.plate.vx},
      {"roller_angles", json::array({f.roller_angles[0], f.roller_angles[1]})},
      {"contacts",
       json::array(
           {{{"normal", f.contacts[0].normal_force}, {"friction", f.contacts[0].friction_force}},
            {{"normal", f.contacts[1].normal_force}, {"friction", f.contacts[1].friction_force}}})},
      {"hall", hall},
      {"pulses", f.pulses},
      {"periods", periods_json(f.periods, 0)},
      {"estimate", estimate_json(f.estimate)},
      {"regime", f.regime},
      {"playing", playing},
      {"speed", speed}};
}

json said_json(const Said& message) {
  json args = json::array();
  for (const SaidArg& a : message.args) {
    json one{{"name", a.name}};
    const double* number = std::get_if<double>(&a.value);
    if (number && std::isfinite(*number))
      one["number"] = *number;
    else if (number)  // JSON has no infinity: it goes as English writes it ("inf")
      one["text"] = describe(*number);
    else if (const std::string* text = std::get_if<std::string>(&a.value))
      one["text"] = web_spelled(*text);  // a field's name, spelled as the page names it
    else
      one["said"] = said_json(*std::get<std::shared_ptr<const Said>>(a.value));
    args.push_back(std::move(one));
  }
  return {{"id", message.id}, {"args", std::move(args)}};
}

json said_or_null(const std::optional<Said>& message) {
  return message ? said_json(*message) : json(nullptr);
}

json problems_json(const std::exception& error) {
  json problems = json::array();
  if (const auto* request = dynamic_cast<const RequestError*>(&error)) {
    for (const FieldProblem& p : request->problems())
      problems.push_back({{"field", p.field},
                          {"value", p.value ? json(*p.value) : json(nullptr)},
                          {"message", web_spelled(p.message)},
                          {"said", said_or_null(p.said)}});
  } else if (const auto* input = dynamic_cast<const InputError*>(&error)) {
    const SourceLocation& where = input->where();
    // A located message from a file (the scene's) keeps its location: it is not the page's.
    const std::string message =
        where.field.empty() ? std::string(input->what()) : without_location(input->what());
    problems.push_back({{"field", where.field.empty() ? "scene" : where.field},
                        {"value", where.field_value ? json(*where.field_value) : json(nullptr)},
                        {"message", web_spelled(message)},
                        {"said", said_or_null(input->said())}});
  } else {
    problems.push_back(
        {{"field", nullptr}, {"value", nullptr}, {"message", error.what()}, {"said", nullptr}});
  }
  return {{"error", fmt::format("the set-up has {} problem{}", problems.size(),
                                problems.size() == 1 ? "" : "s")},
          {"problems", problems}};
}

json file_problem_json(const InputError& error) {
  const std::string place = place_in_file(error.where());
  json problem{{"field", "file"},
               {"value", place.empty() ? json(nullptr) : json(place)},
               {"message", web_spelled(without_location(error.what()))},
               {"said", said_or_null(error.said())}};
  return {{"error", web_spelled(error.what())}, {"problems", json::array({std::move(problem)})}};
}

json error_json(const std::string& message) {
  return {{"error", message}, {"problems", json::array()}};
}

json error_json(const Said& message) {
  return {{"error", english(message)}, {"problems", json::array()}, {"said", said_json(message)}};
}

json live_rig_json(const BoardFeed* feed, const std::vector<std::string>& ports, bool may_choose,
                   int baud) {
  json out{{"ports", may_choose ? json(ports) : json::array()},
           {"may_choose", may_choose},
           {"port", nullptr},
           {"baud", baud},
           {"state", "closed"},
           {"message", nullptr},
           {"said", nullptr},
           {"lines", 0},
           {"log_name", nullptr}};
  if (feed) {
    const BoardFeedStatus s = feed->status();
    out["port"] = s.port;
    out["baud"] = s.baud;
    out["state"] = s.state;
    out["message"] = s.message ? json(*s.message) : json(nullptr);
    out["said"] = said_or_null(s.said);
    out["lines"] = s.lines;
    out["log_name"] = s.log_name.empty() ? json(nullptr) : json(s.log_name);
  }
  return out;
}

json missing_file_json(const std::string& name, double most_recorded_seconds) {
  return error_json(fmt::format(
      "no file \"{}\": the run writes its files when it ends, only those its scene's output part "
      "names, and, for a run longer than {:g} s, neither trajectory.csv nor hall.csv nor "
      "periods.csv (run it with frictionlab run to have them)",
      name, most_recorded_seconds));
}

}  // namespace fl::serve
