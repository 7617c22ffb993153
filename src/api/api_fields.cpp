#include "api/api_fields.hpp"

#include <string_view>

#include "lab/logs/estimate_fields.hpp"
#include "lab/run/summary_fields.hpp"

namespace fl::api {
namespace {

using nlohmann::json;

ApiKey key(const char* name, const char* type, const char* unit, const char* meaning) {
  return {.name = name, .type = type, .unit = unit, .meaning = meaning};
}

ApiKey maybe(const char* name, const char* type, const char* unit, const char* meaning) {
  return {.name = name, .type = type, .unit = unit, .meaning = meaning, .nullable = true};
}

ApiKey column(ApiKey k, const char* csv, double scale = 1.0) {
  k.csv = csv;
  k.csv_scale = scale;
  return k;
}

const char* summary_type(FieldType type) {
  switch (type) {
    case FieldType::kNumber:
    case FieldType::kInteger:
      return "number";
    case FieldType::kText:
      return "string";
    case FieldType::kFlag:
      return "boolean";
    case FieldType::kObject:
      return "object";
  }
  return "object";
}

// What the lab offers: its scenes and the paper's materials.
std::vector<ApiObject> offer_objects() {
  return {
      {"SceneEntry",
       "A scene the lab offers (`GET /api/lab`).",
       {key("name", "string", "", "the name a session asks for"),
        key("title", "string", "", "the scene's title")}},
      {"MaterialEntry",
       "A material of the paper's Table I (`GET /api/lab`).",
       {key("key", "string", "", "`plate.material`'s value for it"),
        key("name", "string", "", "its name in Table I"),
        key("temperatures_k", "number[]", "K", "the temperatures Table I measured it at")}},
      {"Lab",
       "`GET /api/lab`: what the page is offered.",
       {key("scenes", "SceneEntry[]", "", "the scenes, by name"),
        key("materials", "MaterialEntry[]", "", "the paper's Table I"),
        key("version", "string", "", "the lab's version")}},
  };
}

// A session's rig, as compiled from its set-up.
std::vector<ApiObject> rig_objects() {
  return {
      {"PlateBlock",
       "A LEGO part on the plate.",
       {key("part", "string", "", "the part, served as /parts/NAME.glb"),
        key("x", "number", "m", "its centre along the plate from the plate's centre"),
        key("y", "number", "m", "its centre across the plate"),
        key("turn_deg", "number", "", "its turn about the vertical, in degrees")}},
      {"Plate",
       "The friction plate.",
       {key("length", "number", "m", "along the rollers' spacing"),
        key("width", "number", "m", "along the rollers' axes"),
        key("thickness", "number", "m", "the plate's own, blocks not included"),
        key("mass", "number", "kg", "with its blocks and magnets"),
        key("h_c", "number", "m", "its centre of mass above the rollers' contact line"),
        key("material", "string", "", "the plate's material (`plate.material`)"),
        key("blocks", "PlateBlock[]", "", "the LEGO parts on it")}},
      {"Magnet",
       "A magnet on the plate.",
       {key("x", "number", "m", "its centre along the plate from the plate's centre"),
        key("height", "number", "m", "its bottom face above the plate's top face"),
        key("diameter", "number", "m", "its diameter"),
        key("thickness", "number", "m", "its thickness")}},
      {"HallSensor",
       "Where the Hall sensor sits.",
       {key("x", "number", "m", "along the plate's motion from the rollers' midpoint"),
        key("y", "number", "m", "across"), key("z", "number", "m", "up")}},
      {"FramePart",
       "A LEGO part of the rig's frame.",
       {key("part", "string", "", "the part, served as /parts/NAME.glb"),
        key("position", "[number, number, number]", "m", "its position"),
        key("turn_deg", "number", "", "its turn about z after the position, in degrees"),
        key("color", "[number, number, number]", "", "red, green, blue from 0 to 1")}},
      {"PaperValues",
       "What the paper measured for the rig's material (its Table I row).",
       {key("material", "string", "", "the material's name in Table I"),
        key("key", "string", "", "`plate.material`'s value for it"),
        key("temperature_k", "number", "K", "the rollers' temperature of the row"),
        key("period", "number", "s", "the period the paper measured"),
        key("period_err", "number", "s", "its uncertainty"),
        key("mu_k", "number", "", "the paper's mu_k"),
        key("mu_k_err", "number", "", "its uncertainty")}},
      {"AcceptedRange",
       "The values the set-up accepts for a key a student turns, every other value as it is.",
       {key("key", "string", "",
            "the scene key, as a `set` entry names it (`rollers.spacing`, `rollers.speed` or "
            "`drive.motor.duty`, `plate.offset`, `world.duration`)"),
        key("least", "number", "", "the least value accepted, in `unit`"),
        key("most", "number", "", "the most accepted, in `unit`"),
        key("unit", "string", "",
            "the SI unit of least and most (`m`, `rad/s`, `s`; none for a duty)")}},
      {"Rig",
       "A session's rig as compiled from its set-up (`POST /api/sessions`).",
       {key("scene", "string", "", "the scene's name"),
        key("spacing", "number", "m", "l, between the rollers' axes"),
        key("roller_radius", "number", "m", "the rollers' radius"),
        key("roller_length", "number", "m", "the rollers' length"),
        key("roller_sense", "\"inward\" | \"outward\"", "",
            "whether the rollers' tops turn toward each other (restoring) or apart"),
        key("roller_speed_rpm", "number", "", "the rollers' nominal speed, in rpm"),
        key("drive", "boolean", "", "whether a motor and gearbox drive the rollers"),
        maybe("motor_duty", "number", "", "the motor's duty; null without a drive"),
        key("runout", "number", "m", "the rollers' run-out"),
        key("plate", "Plate", "", "the friction plate"),
        key("magnets", "Magnet[]", "", "the magnets on the plate"),
        maybe("sensor", "HallSensor", "", "the Hall sensor; null for a rig without one"),
        key("frame", "FramePart[]", "", "the LEGO frame's parts (none for a bare rig)"),
        key("offset", "number", "m", "where the plate starts, from the rollers' midpoint"),
        key("duration", "number", "s", "the run's simulated length"),
        key("time_step", "number", "s", "the physics step"),
        key("seed", "number", "", "`world.seed`, which draws the sensor's noise"),
        key("gravity", "number", "m/s^2", "g"),
        key("friction_law", "\"slip-dependent\" | \"coulomb\"", "",
            "whether mu depends on the slip speed"),
        key("mu_k", "number", "", "the kinetic friction coefficient set"),
        key("temperature_k", "number", "K", "the rollers' temperature at the start"),
        key("period_thin", "number", "s", "the paper's period, pi sqrt(2 l / (mu_k g))"),
        maybe("period_thick", "number", "s",
              "the period with the plate's thickness; null when the rollers do not restore it"),
        maybe("omega", "number", "rad/s", "2 pi / period_thick; null likewise"),
        maybe("tipping_amplitude", "number", "m",
              "the amplitude beyond which the plate tips off a roller; null likewise"),
        maybe("paper", "PaperValues", "",
              "what the paper measured; null when the friction is not a Table I row"),
        key("accepts", "AcceptedRange[]", "",
            "what each key a student turns accepts with the rest of the set-up as it is: the "
            "page's controls offer these ranges only")}},
      {"Session",
       "`POST /api/sessions`'s answer (201).",
       {key("id", "string", "", "the session's public id; the class's table lists it"),
        key("key", "string", "",
            "the session's secret: only requests that carry it control the session"),
        key("rig", "Rig", "", "the compiled rig")}},
  };
}

// A refusal, and what a session's stream and controls send.
std::vector<ApiObject> run_objects() {
  return {
      {"Problem",
       "One problem of a request the lab refused, by field.",
       {maybe("field", "string", "",
              "the request's key (`scene`, `set`, `name`; `file` for a measurement's file)"),
        maybe("value", "string", "",
              "the entry at fault (a `set` entry; the place in the file, `log.csv:3:5`)"),
        key("message", "string", "", "what was expected, what was found, what to do"),
        maybe("said", "Said", "",
              "the message as the catalogues (assets/locales) say it, for a page to say in its "
              "reader's language; null where the lab says it in English only")}},
      {"Said",
       "A message the lab says: its id in assets/locales/LANG.ftl and its values.",
       {key("id", "string", "", "the message's id (`check-rollers-overlap`)"),
        key("args", "SaidArg[]", "", "its values, by the names its pattern uses")}},
      {"SaidArg",
       "One value of a message: exactly one of `number`, `text` and `said`.",
       {key("name", "string", "", "the name its pattern uses (`spacing_mm`)"),
        {.name = "number",
         .type = "number",
         .meaning = "a number, in the unit the name says",
         .optional = true},
        {.name = "text", .type = "string", .meaning = "a text said as it is", .optional = true},
        {.name = "said",
         .type = "Said",
         .meaning = "another message, said in the same language",
         .optional = true}}},
      {"ErrorBody",
       "A 4xx's body.",
       {key("error", "string", "", "what went wrong, in a line"),
        key("problems", "Problem[]", "", "each problem by field (none for the API's own)"),
        {.name = "said",
         .type = "Said",
         .meaning = "the error as the catalogues say it, where they do; absent otherwise",
         .optional = true},
        {.name = "refused",
         .type = "boolean",
         .meaning = "true when the lab is full (503); absent otherwise",
         .optional = true}}},
      {"ContactForce",
       "A roller's contact with the plate.",
       {key("normal", "number", "N", "the normal force on the plate"),
        key("friction", "number", "N", "the friction force on the plate, along its motion")}},
      {"Estimate",
       "The rig's estimator's statistics of the accepted periods.",
       {key("periods_used", "number", "", "N, the accepted periods"),
        key("periods_discarded", "number", "", "the periods it rejected"),
        key("pulses", "number", "", "the Hall pulses it detected"),
        key("period", "number", "s", "the mean period"),
        maybe("period_sd", "number", "s", "the periods' standard deviation; null below two"),
        maybe("period_se", "number", "s", "the standard error of their mean; null below two"),
        key("mu_k", "number", "", "mu_k through the paper's formula"),
        maybe("mu_k_err", "number", "",
              "mu_k sqrt((dl/l)^2 + (2 dT/T)^2), dl = 2 mm; null below two periods"),
        maybe("mu_k_err_worst", "number", "",
              "the paper's worst case, mu_k (dl/l + 2 dT/T); null below two periods")}},
      {"LabState",
       "`event: state`: the run now, and what came since the last event.",
       {key("t", "number", "s", "the simulated time"),
        key("x", "number", "m", "the plate's centre along its motion"),
        maybe("x_theory", "number", "m",
              "where the thick plate's theory has the plate now, from where the run started; "
              "null when the rollers do not restore the plate"),
        key("y", "number", "m", "the plate's centre across"), key("z", "number", "m", "its height"),
        key("pitch", "number", "rad", "its tilt about the rollers' axes"),
        key("yaw", "number", "rad", "its turn about the vertical"),
        key("vx", "number", "m/s", "its speed along its motion"),
        key("roller_angles", "[number, number]", "rad", "the rollers' angles"),
        key("contacts", "ContactForce[]", "", "the two rollers' contacts"),
        key("hall", "HallPoint[]", "", "the Hall samples since the last event"),
        key("pulses", "number[]", "s", "the pulses detected since the last event"),
        key("periods", "PeriodRow[]", "", "the periods judged since the last event"),
        maybe("estimate", "Estimate", "", "the estimate so far; null before a period"),
        key("regime", "string", "", "the diagnosis so far"),
        key("playing", "boolean", "", "whether the run plays"),
        key("speed", "PlaybackSpeed", "", "its playback speed")}},
      {"ControlReply",
       "`POST /api/sessions/ID/control`'s answer.",
       {key("t", "number", "s", "the simulated time"),
        key("playing", "boolean", "", "whether the run plays"),
        key("speed", "PlaybackSpeed", "", "its playback speed")}},
      {"Closed",
       "`event: closed`: the server is stopping; the stream ends after it.",
       {key("message", "string", "", "what happened and what to do")}},
      {"Failure",
       "`event: failed`: a guard stopped the run (its summary follows as `done`).",
       {key("message", "string", "", "the guard's message")}},
  };
}

// The live rig (the rig's board on a serial port) and the class's table.
std::vector<ApiObject> live_rig_objects() {
  return {
      {"LiveRig",
       "`GET /api/rig`: the serial ports the server sees and the one open (or last open).",
       {key("ports", "string[]", "", "the ports a page may open (none on a shared server)"),
        key("may_choose", "boolean", "", "whether this page may open or close a port"),
        maybe("port", "string", "", "the port open or last open; null before one"),
        maybe("baud", "number", "", "its baud rate; null before a port"),
        key("state", "BoardPortState", "", "the port's state"),
        maybe("message", "string", "", "what happened and what to do; null while all is well"),
        maybe("said", "Said", "", "the message as the catalogues say it; null where they do not"),
        key("lines", "number", "", "the lines received"),
        maybe("log_name", "string", "", "the raw log's download name; null before a line")}},
      {"LiveRigEvent",
       "`event: rig`: what the live rig sent since the last event, through the rig's estimator "
       "with the session's spacing.",
       {maybe("port", "string", "", "the port"),
        key("state", "BoardPortState", "", "the port's state"),
        maybe("message", "string", "", "what happened and what to do; null while all is well"),
        maybe("said", "Said", "", "the message as the catalogues say it; null where they do not"),
        key("lines", "number", "", "the lines received"),
        key("run", "number", "",
            "the board's restarts: a new value starts the rig's plot and periods again"),
        key("hall", "HallPoint[]", "", "the samples since the last event (the last 10 s at most)"),
        key("periods", "PeriodRow[]", "", "the periods judged since the last event"),
        maybe("estimate", "Estimate", "", "the estimate so far; null before a period"),
        key("geometry", "PulseGeometry", "", "the pulses per period recognised"),
        key("spacing", "number", "m", "the l mu_k is computed with: the session's rig's")}},
      {"ClassRow",
       "One session's row of `GET /api/class` (and of class.csv): its set-up and result so far.",
       {column(key("session", "string", "", "the session's id"), "session"),
        column(maybe("name", "string", "", "who runs it; null when not given"), "name"),
        column(key("scene", "string", "", "the scene's name"), "scene"),
        column(maybe("material", "string", "",
                     "the plate's material in Table I; null for a mu_k given as a number"),
               "material"),
        column(key("temperature_k", "number", "K", "the rollers' temperature at the start"),
               "temperature_k"),
        column(key("spacing", "number", "m", "l"), "spacing_mm", 1e3),
        column(key("h_c", "number", "m", "the plate's centre of mass above the contact line"),
               "h_c_mm", 1e3),
        column(key("state", "SessionState", "", "where the run stands"), "state"),
        column(key("t", "number", "s", "the simulated time reached"), "t_s"),
        column(maybe("period", "number", "s", "the mean accepted period; null before one"),
               "period_s"),
        column(maybe("period_err", "number", "s",
                     "the standard error of that mean (or of the fit); null below two periods"),
               "period_err_s"),
        column(maybe("period_from", "PeriodFrom", "", "where the period comes from"),
               "period_from"),
        column(maybe("mu_k", "number", "", "through the paper's formula; null before a period"),
               "mu_k"),
        column(maybe("mu_k_err", "number", "", "in quadrature; null below two periods"),
               "mu_k_err"),
        column(maybe("paper_period", "number", "s", "the paper's period for the material"),
               "paper_period_s"),
        column(maybe("paper_mu_k", "number", "", "the paper's mu_k for the material"),
               "paper_mu_k")}},
      {"ClassLiveRig",
       "The live rig as the class's table shows it.",
       {maybe("port", "string", "", "the port"),
        key("state", "BoardPortState", "", "the port's state"),
        key("lines", "number", "", "the lines received")}},
      {"ClassTable",
       "`GET /api/class`: every open session, and the live rig.",
       {key("sessions", "ClassRow[]", "", "one row a session"),
        maybe("rig", "ClassLiveRig", "", "the live rig; null when no port was opened")}},
  };
}

// A measurement file's estimate: the keys of `frictionlab estimate --json` the page shows, each
// typed and explained where the estimate's keys are declared (lab/logs/estimate_fields.hpp).
ApiObject measurement_estimate() {
  ApiObject o{.name = "MeasurementEstimate",
              .meaning =
                  "`POST /api/estimate?name=FILE`: a measurement file's estimate, the keys "
                  "of `frictionlab estimate --json` (docs/cli.md) the page shows."};
  for (const char* name :
       {"file", "instrument", "channel", "samples", "sample_rate_hz", "duration_s", "periods_used",
        "periods_discarded", "period_s", "period_std_s", "period_sem_s", "mu_k", "mu_k_err_worst",
        "mu_k_err_quadrature", "mu_k_thick", "spacing_m", "amplitude", "amplitude_unit"}) {
    for (const EstimateField& f : estimate_fields())
      if (std::string_view(f.json) == name)
        o.keys.push_back({.name = f.json,
                          .type = summary_type(f.type),
                          .unit = f.unit,
                          .meaning = f.meaning,
                          .nullable = f.null_when != nullptr});
  }
  return o;
}

ApiDeclaration declare() {
  ApiDeclaration d;
  d.aliases = {
      {"PeriodRow", "[number, number, number, boolean]",
       "One period as the estimator judged it: [start, end, period, accepted], in seconds."},
      {"HallPoint", "[number, number]",
       "One Hall sample: [t, adc], t in seconds from the run's first sample."},
      {"PlaybackSpeed", "1 | 0.25 | 0.0625", "How fast simulated time runs against the wall's."},
      {"BoardPortState",
       "\"closed\" | \"waiting\" | \"receiving\" | \"unplugged\" | \"failed\" | \"full\"",
       "The live rig's serial port: none open, open with nothing yet, lines coming, gone, failed, "
       "or its log full."},
      {"PulseGeometry", "\"one-pulse\" | \"pair\" | \"unknown\"",
       "How many Hall pulses the magnets give per period, as the rig's estimator recognised it."},
      {"SessionState", "\"paused\" | \"playing\" | \"done\"", "Where a session's run stands."},
      {"PeriodFrom", "\"sensor\" | \"trajectory\"",
       "Where a period comes from: the Hall sensor's estimator, or the fit to the plate's motion."},
  };
  for (auto* group : {&offer_objects, &rig_objects, &run_objects, &live_rig_objects}) {
    std::vector<ApiObject> part = group();
    d.objects.insert(d.objects.end(), part.begin(), part.end());
  }
  d.objects.push_back(measurement_estimate());
  // The run's summary (the `done` event, summary.json): its keys are the run's fields'.
  ApiObject summary{.name = "RunSummaryJson",
                    .meaning = "`event: done`: the run's summary, summary.json's object.",
                    .typed_elsewhere = true};
  for (const SummaryField& f : summary_fields())
    if (f.json != nullptr && !f.timing)
      summary.keys.push_back({.name = f.json,
                              .type = summary_type(f.type),
                              .unit = f.unit,
                              .meaning = f.meaning,
                              .nullable = f.null_when != nullptr,
                              .optional = f.omit_when_null});
  d.objects.push_back(std::move(summary));
  return d;
}

}  // namespace

const ApiDeclaration& api_declaration() {
  static const ApiDeclaration declaration = declare();
  return declaration;
}

json api_declaration_json() {
  json aliases = json::object();
  json objects = json::object();
  for (const ApiAlias& a : api_declaration().aliases) aliases[a.name] = a.type;
  for (const ApiObject& o : api_declaration().objects) {
    json keys = json::array();
    for (const ApiKey& k : o.keys) {
      json key{
          {"name", k.name}, {"type", k.type}, {"nullable", k.nullable}, {"optional", k.optional}};
      if (k.csv != nullptr) {
        key["csv"] = k.csv;
        key["csv_scale"] = k.csv_scale;
      }
      keys.push_back(std::move(key));
    }
    objects[o.name] = std::move(keys);
  }
  return {{"aliases", std::move(aliases)}, {"objects", std::move(objects)}};
}

}  // namespace fl::api
