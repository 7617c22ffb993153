// cpp-httplib's server with every request bounded, however it is sent. Debian 12's cpp-httplib
// (0.11) reads a request line, its headers and a chunked or length-less body into memory without
// limit (set_payload_max_length bounds a Content-Length only): one client could grow the server by
// the gigabyte. This server reads each connection through its own stream, which gives a request
// at most `most_head_bytes` for its line and headers and `most_body_bytes` (plus the chunks'
// framing) for its body, and ends a connection whose request went past them or left its body
// unread. The library's own parsing, routing and handlers are unchanged.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <httplib.h>

namespace fl::serve {

// Which bound the request being answered on this thread went past (none, its head, its body).
enum class RequestBound { kWithin, kHeadTooLarge, kBodyTooLarge };

class BoundedServer : public httplib::Server {
 public:
  BoundedServer(std::size_t most_head_bytes, std::size_t most_body_bytes);

  // Lets a request to `path` (exactly: a file a page sends; a `*` in it stands for one segment,
  // "/api/sessions/*/report") carry a body of `most_bytes` instead; call before listening.
  void allow_larger_body(std::string path, std::size_t most_bytes);
  // The most bytes a request to `path` may carry in its body.
  std::size_t most_body_bytes(const std::string& path) const;

  // Called on the request's own thread after each request is answered, however it ended (a
  // body cut short, a handler's exception): what a pre-routing handler took for the request is
  // given back there. Set before listening.
  void on_request_done(std::function<void()> done) { request_done_ = std::move(done); }

  // For the error handler, answering on the request's own thread.
  static RequestBound bound_passed();

 private:
  bool process_and_close_socket(socket_t sock) override;

  const std::size_t most_head_bytes_;
  const std::size_t most_body_bytes_;
  std::vector<std::pair<std::string, std::size_t>> larger_bodies_;
  std::function<void()> request_done_;
};

}  // namespace fl::serve
