#include "serve/board_feed.hpp"

#include <chrono>
#include <ctime>
#include <filesystem>

#include <fmt/chrono.h>
#include <fmt/format.h>

#include "io/appending_file.hpp"
#include "io/input_error.hpp"

namespace fl::serve {
namespace {

// The local time now, for the log's name (the one a class finds its capture by) and messages.
std::tm local_now() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  ::localtime_r(&now, &local);
  return local;
}

}  // namespace

BoardFeed::BoardFeed(std::string port, int baud, std::string record_dir, std::size_t most_log_bytes)
    : most_log_bytes_(most_log_bytes),
      record_dir_(std::move(record_dir)),
      capture_(port, HallLogOptions{}) {
  status_.port = port;
  status_.baud = baud;
  status_.state = "waiting";
  try {
    port_ = std::make_unique<SerialPort>(port, baud);
  } catch (const InputError& e) {
    status_.state = "failed";
    status_.message = std::string(e.what());
    if (e.said()) status_.said = said("port-failed", {arg("port", port), arg("why", *e.said())});
    return;
  }
  thread_ = std::thread([this] { read_port(); });
}

BoardFeed::~BoardFeed() {
  close();
}

void BoardFeed::close() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  const std::lock_guard lock(mutex_);
  if (status_.state == "waiting" || status_.state == "receiving") {
    status_.state = "closed";
    status_.message = std::nullopt;
    status_.said = std::nullopt;
  }
  if (record_) {
    record_->sync();
    record_.reset();
  }
}

void BoardFeed::read_port() {
  std::string bytes;
  while (!stop_) {
    bytes.clear();
    const bool open = port_->read_some(&bytes, 100);
    if (!take(bytes, !open)) break;
  }
  port_.reset();
}

BoardFeed::BoardFeed(FedFromOutside, std::string port, int baud, std::size_t most_log_bytes)
    : most_log_bytes_(most_log_bytes), capture_(port, HallLogOptions{}) {
  status_.port = std::move(port);
  status_.baud = baud;
  status_.state = "waiting";
}

bool BoardFeed::feed(std::string_view bytes, bool ended) {
  {
    const std::lock_guard lock(mutex_);
    if (status_.state != "waiting" && status_.state != "receiving" && status_.state != "failed")
      return false;
  }
  return take(bytes, ended);
}

bool BoardFeed::take(std::string_view bytes, bool ended) {
  if (!lines_in(bytes, ended)) {
    const std::lock_guard lock(mutex_);
    end("full", said("port-log-full", {arg("megabytes", most_log_bytes_ >> 20),
                                       arg("minutes", most_log_bytes_ / (20 * 1000 * 60))}));
    return false;
  }
  if (ended) {
    const std::lock_guard lock(mutex_);
    end("unplugged", said("port-unplugged", {arg("port", status_.port),
                                             arg("time", fmt::format("{:%H:%M:%S}", local_now())),
                                             arg("lines", status_.lines)}));
    return false;
  }
  return true;
}

bool BoardFeed::lines_in(std::string_view bytes, bool ended) {
  const std::lock_guard lock(mutex_);
  const LiveCapture::LineSink keep = [this](std::string_view text) {
    if (log_.size() + text.size() > most_log_bytes_) return false;
    if (status_.log_name.empty())
      status_.log_name = fmt::format("rig-{:%Y%m%d-%H%M%S}.log", local_now());
    log_.append(text);
    record(text);
    ++status_.lines;
    if (status_.state != "failed") status_.state = "receiving";
    return true;
  };
  // The lines are kept when they give no samples; the page says why.
  const LiveCapture::ErrorSink refused = [this](const InputError& e) {
    status_.state = "failed";
    status_.message = std::string(e.what());
    status_.said = e.said();
  };
  return capture_.add(bytes, ended, keep, {}, refused);
}

// The record file is made with the first line (io/appending_file.hpp: each line written whole as
// it comes, so it holds everything received however the server ends). Under the lock.
void BoardFeed::record(std::string_view bytes) {
  if (record_dir_.empty() || record_failed_) return;
  try {
    if (!record_) {
      record_path_ = (std::filesystem::path(record_dir_) / status_.log_name).string();
      record_ = std::make_unique<AppendingFile>(record_path_, "the rig's log");
    }
    record_->write(bytes);
  } catch (const InputError& e) {
    // The page's download still has every line: it says where the record stopped.
    record_failed_ = true;
    record_.reset();
    // Said without the folder's place on the laptop: a page reads it.
    status_.message = fmt::format(
        "{} in the --record folder: {}; the page's download still has "
        "the log",
        status_.log_name, without_location(e.what()));
    status_.said = std::nullopt;
  }
}

// Under the lock.
void BoardFeed::end(const std::string& state, const Said& message) {
  status_.state = state;
  status_.message = english(message);
  status_.said = message;
}

BoardFeedStatus BoardFeed::status() const {
  const std::lock_guard lock(mutex_);
  return status_;
}

std::string BoardFeed::raw_log() const {
  const std::lock_guard lock(mutex_);
  return log_;
}

std::string BoardFeed::record_path() const {
  const std::lock_guard lock(mutex_);
  return record_path_;
}

BoardFeed::Slice BoardFeed::samples_from(int run, std::size_t from) const {
  const std::lock_guard lock(mutex_);
  Slice out;
  const std::vector<LogSample>& samples = capture_.samples();
  out.run = capture_.run();
  out.first = run == out.run ? std::min(from, samples.size()) : 0;
  out.samples.assign(samples.begin() + static_cast<std::ptrdiff_t>(out.first), samples.end());
  return out;
}

}  // namespace fl::serve
