#include "serve/bounded_server.hpp"

#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

namespace fl::serve {
namespace {

// The chunks' framing ("4000\r\n" before each, "\r\n" after) a chunked body may carry beyond
// its bytes: a 64 KiB body in chunks of 64 bytes or more.
constexpr std::size_t kMostFraming = 16 * 1024;
constexpr std::size_t kReadBuffer = 4096;
// How often a connection waiting for its next request looks whether the server stops [ms].
constexpr int kWaitSliceMs = 100;

int milliseconds(time_t sec, time_t usec) {
  return static_cast<int>(sec * 1000 + usec / 1000);
}

// poll() for `events` within `timeout_ms`, through interruptions.
bool wait_for(int sock, short events, int timeout_ms) {
  pollfd fd{sock, events, 0};
  int n = 0;
  do {
    n = ::poll(&fd, 1, timeout_ms);
  } while (n < 0 && errno == EINTR);
  return n > 0;
}

bool ip_and_port(const sockaddr_storage& address, socklen_t length, std::string& ip, int& port) {
  if (address.ss_family == AF_INET)
    port = ntohs(reinterpret_cast<const sockaddr_in*>(&address)->sin_port);
  else if (address.ss_family == AF_INET6)
    port = ntohs(reinterpret_cast<const sockaddr_in6*>(&address)->sin6_port);
  else
    return false;
  std::array<char, NI_MAXHOST> text{};
  if (::getnameinfo(reinterpret_cast<const sockaddr*>(&address), length, text.data(), text.size(),
                    nullptr, 0, NI_NUMERICHOST) != 0)
    return false;
  ip = text.data();
  return true;
}

// A connection's socket as cpp-httplib's own stream reads and writes it, but each request may
// read only so many bytes: its head so many, then its body so many.
class BoundedStream final : public httplib::Stream {
 public:
  BoundedStream(socket_t sock, int read_timeout_ms, int write_timeout_ms)
      : sock_(sock), read_timeout_ms_(read_timeout_ms), write_timeout_ms_(write_timeout_ms) {}

  bool is_readable() const override {
    return offset_ < filled_ || wait_for(sock_, POLLIN, read_timeout_ms_);
  }
  bool is_writable() const override {
    return wait_for(sock_, POLLOUT, write_timeout_ms_) && peer_is_there();
  }
  ssize_t read(char* ptr, std::size_t size) override {
    if (left_ == 0) {
      passed_ = in_body_ ? RequestBound::kBodyTooLarge : RequestBound::kHeadTooLarge;
      return -1;
    }
    size = std::min(size, left_);
    if (offset_ == filled_) {
      if (!wait_for(sock_, POLLIN, read_timeout_ms_)) return -1;
      ssize_t n = 0;
      do {
        n = ::recv(sock_, buffer_.data(), buffer_.size(), 0);
      } while (n < 0 && errno == EINTR);
      if (n <= 0) return n;
      offset_ = 0;
      filled_ = static_cast<std::size_t>(n);
    }
    const std::size_t n = std::min(size, filled_ - offset_);
    std::memcpy(ptr, buffer_.data() + offset_, n);
    offset_ += n;
    left_ -= n;
    if (in_body_) body_read_ += n;
    return static_cast<ssize_t>(n);
  }
  ssize_t write(const char* ptr, std::size_t size) override {
    if (!is_writable()) return -1;
    ssize_t n = 0;
    do {
      n = ::send(sock_, ptr, size, MSG_NOSIGNAL);
    } while (n < 0 && errno == EINTR);
    return n;
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getpeername(sock_, reinterpret_cast<sockaddr*>(&address), &length) == 0)
      ip_and_port(address, length, ip, port);
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getsockname(sock_, reinterpret_cast<sockaddr*>(&address), &length) == 0)
      ip_and_port(address, length, ip, port);
  }
  socket_t socket() const override { return sock_; }

  // A new request begins: its line and headers may read `most` bytes.
  void begin_head(std::size_t most) {
    left_ = most;
    in_body_ = false;
    body_read_ = 0;
    passed_ = RequestBound::kWithin;
  }
  // Its head was read: its body may read `most` bytes.
  void begin_body(std::size_t most) {
    left_ = most;
    in_body_ = true;
  }
  std::size_t body_read() const { return body_read_; }
  RequestBound passed() const { return passed_; }
  // Whether the next request has come (bytes buffered or readable) within `timeout_ms`, looking
  // every slice whether `go_on` still holds.
  template <typename GoOn>
  bool next_request_within(int timeout_ms, GoOn go_on) const {
    if (offset_ < filled_) return true;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
    while (go_on()) {
      if (wait_for(sock_, POLLIN, kWaitSliceMs)) return true;
      if (std::chrono::steady_clock::now() >= deadline) return false;
    }
    return false;
  }

 private:
  // As cpp-httplib's is_socket_alive: a peer that closed makes the socket readable with nothing.
  bool peer_is_there() const {
    pollfd fd{sock_, POLLIN, 0};
    const int n = ::poll(&fd, 1, 0);
    if (n == 0) return true;
    if (n < 0) return errno != EBADF;
    char byte = 0;
    return ::recv(sock_, &byte, 1, MSG_PEEK) > 0;
  }

  const socket_t sock_;
  const int read_timeout_ms_;
  const int write_timeout_ms_;
  std::array<char, kReadBuffer> buffer_{};
  std::size_t offset_ = 0;
  std::size_t filled_ = 0;
  std::size_t left_ = 0;  // bytes this part of the request may still read
  bool in_body_ = false;
  std::size_t body_read_ = 0;
  RequestBound passed_ = RequestBound::kWithin;
};

// The stream of the connection this thread serves, for the error handler.
thread_local const BoundedStream* t_stream = nullptr;

// What a request's headers say of its body: its length, or none known (chunked, or sent without
// a length by a method that has a body; GET, HEAD, DELETE and OPTIONS without one have none).
std::optional<std::uint64_t> declared_length(const httplib::Request& req) {
  if (req.has_header("Transfer-Encoding")) return std::nullopt;
  if (!req.has_header("Content-Length")) {
    const bool bodiless = req.method == "GET" || req.method == "HEAD" || req.method == "DELETE" ||
                          req.method == "OPTIONS";
    return bodiless ? std::optional<std::uint64_t>(0) : std::nullopt;
  }
  const std::string text = req.get_header_value("Content-Length");
  std::uint64_t length = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), length);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return length;
}

}  // namespace

BoundedServer::BoundedServer(std::size_t most_head_bytes, std::size_t most_body_bytes)
    : most_head_bytes_(most_head_bytes), most_body_bytes_(most_body_bytes) {
  // A Content-Length beyond every path's bound is refused (413) by the library before a byte of
  // it is read; one beyond its own path's bound, by the stream (process_and_close_socket).
  set_payload_max_length(most_body_bytes);
}

void BoundedServer::allow_larger_body(std::string path, std::size_t most_bytes) {
  larger_bodies_.emplace_back(std::move(path), most_bytes);
  std::size_t most = most_body_bytes_;
  for (const auto& [p, bytes] : larger_bodies_) most = std::max(most, bytes);
  set_payload_max_length(most);
}

namespace {

// Whether `path` is `pattern`, where a `*` in the pattern stands for one segment (no '/').
bool path_matches(std::string_view pattern, std::string_view path) {
  const std::size_t star = pattern.find('*');
  if (star == std::string_view::npos) return pattern == path;
  const std::string_view before = pattern.substr(0, star);
  const std::string_view after = pattern.substr(star + 1);
  if (path.size() < before.size() + after.size() + 1 || !path.starts_with(before) ||
      !path.ends_with(after))
    return false;
  const std::string_view segment =
      path.substr(before.size(), path.size() - before.size() - after.size());
  return segment.find('/') == std::string_view::npos;
}

}  // namespace

std::size_t BoundedServer::most_body_bytes(const std::string& path) const {
  for (const auto& [p, bytes] : larger_bodies_)
    if (path_matches(p, path)) return bytes;
  return most_body_bytes_;
}

RequestBound BoundedServer::bound_passed() {
  return t_stream != nullptr ? t_stream->passed() : RequestBound::kWithin;
}

// cpp-httplib's connection loop (keep-alive, at most keep_alive_max_count_ requests) over the
// bounded stream; the connection ends after a request that passed a bound or left its body.
bool BoundedServer::process_and_close_socket(socket_t sock) {
  BoundedStream stream(sock, milliseconds(read_timeout_sec_, read_timeout_usec_),
                       milliseconds(write_timeout_sec_, write_timeout_usec_));
  // This thread's stream while it serves the connection, whatever ends it.
  struct Current {
    explicit Current(const BoundedStream* s) { t_stream = s; }
    ~Current() { t_stream = nullptr; }
    Current(const Current&) = delete;
    Current& operator=(const Current&) = delete;
  } current(&stream);
  const auto serving = [this] { return svr_sock_ != INVALID_SOCKET; };
  const int keep_alive_ms = static_cast<int>(keep_alive_timeout_sec_ * 1000);
  bool ok = false;
  for (std::size_t count = keep_alive_max_count_;
       count > 0 && serving() && stream.next_request_within(keep_alive_ms, serving); --count) {
    stream.begin_head(most_head_bytes_);
    bool closed = false;
    // The body's length its headers declare (none known: chunked, or no length); the next
    // request begins after a body read whole only. Unset: the head itself was refused.
    std::optional<std::optional<std::uint64_t>> length;
    ok = process_request(stream, count == 1, closed, [&](httplib::Request& req) {
      length = declared_length(req);
      // A Content-Length beyond the path's bound: not a byte of the body is read.
      const std::size_t most = most_body_bytes(req.path);
      stream.begin_body(*length && **length > most ? 0 : most + kMostFraming);
    });
    if (request_done_) request_done_();
    const bool read_whole = length && *length && stream.body_read() >= **length;
    if (!ok || closed || !read_whole || stream.passed() != RequestBound::kWithin) break;
  }
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
  return ok;
}

}  // namespace fl::serve
