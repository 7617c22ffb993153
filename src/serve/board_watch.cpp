#include "serve/board_watch.hpp"

#include "lab/run/hall_estimator.hpp"
#include "serve/api_json.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;

}  // namespace

BoardWatch::BoardWatch(const LogSetUp& set_up) : set_up_(set_up) {}

LogSetUp BoardWatch::set_up_for(const CompiledRig& rig) {
  return LogSetUp{rig.rollers.spacing, LogSetUp{}.spacing_err, rig.world.gravity,
                  fl_estimator::kAutoGeometry, std::nullopt};
}

std::optional<json> BoardWatch::next(const std::shared_ptr<const BoardFeed>& feed) {
  const BoardFeedStatus status = feed->status();
  BoardFeed::Slice slice = feed->samples_from(feed_run_, next_sample_);
  if (feed != feed_ || slice.run != feed_run_ || !live_) {
    feed_ = feed;
    feed_run_ = slice.run;
    ++run_;
    live_ = std::make_unique<LiveLogEstimate>(set_up_, /*keep_samples=*/false);
    periods_sent_ = 0;
    if (slice.first != 0) slice = feed->samples_from(feed_run_, 0);
  }
  next_sample_ = slice.first + slice.samples.size();
  json hall = json::array();
  if (!slice.samples.empty()) {
    // Every sample goes through the estimator; the event carries the last 10 s of them.
    std::size_t shown = 0;
    const double last = slice.samples.back().t_s;
    while (slice.samples[shown].t_s < last - kShownSeconds) ++shown;
    for (std::size_t i = 0; i < slice.samples.size(); ++i) {
      live_->add(slice.samples[i]);
      if (i >= shown)
        hall.push_back(
            json::array({static_cast<double>(live_->last_t_us()) * 1e-6, slice.samples[i].adc}));
    }
  }
  const std::string sent = status.state + '\n' + status.message.value_or("") + '\n' +
                           std::to_string(status.lines) + '\n' + std::to_string(run_);
  const std::vector<EstimatedPeriod>& periods = live_->host().periods();
  if (hall.empty() && periods.size() == periods_sent_ && sent == status_sent_) return std::nullopt;
  status_sent_ = sent;
  json out{{"port", status.port},
           {"state", status.state},
           {"message", status.message ? json(*status.message) : json(nullptr)},
           {"said", said_or_null(status.said)},
           {"lines", status.lines},
           {"run", run_},
           {"hall", std::move(hall)},
           {"periods", periods_json(periods, periods_sent_)},
           {"spacing", set_up_.spacing}};
  out.update(board_reading_json(*live_));
  periods_sent_ = periods.size();
  return out;
}

json board_reading_json(const LiveLogEstimate& live) {
  const fl_estimator::PeriodEstimator& estimator = live.host().estimator();
  return {{"estimate", estimate_json(estimator_report(estimator.stats()))},
          {"geometry", geometry_name(estimator.geometry())}};
}

}  // namespace fl::serve
