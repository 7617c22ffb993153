#include "hall_log/measurement_zip.hpp"

#include <algorithm>
#include <cstring>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unzip.h>

#include "io/input_error.hpp"
#include "io/text_file.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

constexpr std::size_t kMostEntries = 1000;

// minizip reads the archive through these, from memory.
struct Memory {
  std::string_view bytes;
  std::size_t at = 0;
};

voidpf open_memory(voidpf opaque, const void*, int) {
  return opaque;
}
uLong read_memory(voidpf, voidpf stream, void* buffer, uLong size) {
  auto* m = static_cast<Memory*>(stream);
  const std::size_t n = std::min<std::size_t>(size, m->bytes.size() - m->at);
  std::memcpy(buffer, m->bytes.data() + m->at, n);
  m->at += n;
  return static_cast<uLong>(n);
}
uLong write_memory(voidpf, voidpf, const void*, uLong) {
  return 0;
}
ZPOS64_T tell_memory(voidpf, voidpf stream) {
  return static_cast<Memory*>(stream)->at;
}
long seek_memory(voidpf, voidpf stream, ZPOS64_T offset, int origin) {
  auto* m = static_cast<Memory*>(stream);
  const std::size_t base = origin == ZLIB_FILEFUNC_SEEK_SET   ? 0
                           : origin == ZLIB_FILEFUNC_SEEK_CUR ? m->at
                                                              : m->bytes.size();
  if (offset > m->bytes.size() - std::min(base, m->bytes.size())) return -1;
  m->at = base + static_cast<std::size_t>(offset);
  return 0;
}
int close_memory(voidpf, voidpf) {
  return 0;
}
int error_memory(voidpf, voidpf) {
  return 0;
}

class Archive {
 public:
  Archive(std::string_view bytes, const std::string& name) : memory_{bytes}, name_(name) {
    zlib_filefunc64_def io{};
    io.zopen64_file = open_memory;
    io.zread_file = read_memory;
    io.zwrite_file = write_memory;
    io.ztell64_file = tell_memory;
    io.zseek64_file = seek_memory;
    io.zclose_file = close_memory;
    io.zerror_file = error_memory;
    io.opaque = &memory_;
    zip_ = unzOpen2_64("memory", &io);
    if (zip_ == nullptr)
      throw InputError(SourceLocation(name),
                       "the zip is damaged: its table of entries cannot "
                       "be read (a file cut short?); export it again");
  }
  Archive(const Archive&) = delete;
  Archive& operator=(const Archive&) = delete;
  ~Archive() { unzClose(zip_); }

  std::vector<std::string> names() {
    std::vector<std::string> out;
    for (int at = unzGoToFirstFile(zip_); at == UNZ_OK; at = unzGoToNextFile(zip_)) {
      if (out.size() >= kMostEntries)
        throw InputError(SourceLocation(name_),
                         fmt::format("the zip holds more than {} entries; a phyphox export "
                                     "holds a few",
                                     kMostEntries));
      char entry[512] = {};
      unz_file_info64 info{};
      if (unzGetCurrentFileInfo64(zip_, &info, entry, sizeof entry, nullptr, 0, nullptr, 0) !=
          UNZ_OK)
        throw damaged(out.size());
      out.emplace_back(entry);
    }
    return out;
  }

  // The first kMostTextFileBytes + 1 bytes of an entry at most.
  std::string text_of(const std::string& entry) {
    if (unzLocateFile(zip_, entry.c_str(), 1) != UNZ_OK || unzOpenCurrentFile(zip_) != UNZ_OK)
      throw damaged_at(entry);
    std::string text;
    char buffer[1 << 16];
    int got = 0;
    while ((got = unzReadCurrentFile(zip_, buffer, sizeof buffer)) > 0) {
      text.append(buffer, static_cast<std::size_t>(got));
      if (text.size() > kMostTextFileBytes) break;
    }
    const int closed = unzCloseCurrentFile(zip_);
    if (text.size() > kMostTextFileBytes)
      throw InputError(SourceLocation(name_),
                       fmt::format("its entry \"{}\" inflates to more than {} MiB; a phone's "
                                   "recording is a few MiB",
                                   entry, kMostTextFileBytes >> 20));
    if (got < 0 || closed != UNZ_OK) throw damaged_at(entry);
    return text;
  }

 private:
  InputError damaged(std::size_t entry) const {
    return InputError(
        SourceLocation(name_),
        fmt::format("the zip is damaged at its entry {}; export it again", entry + 1));
  }
  InputError damaged_at(const std::string& entry) const {
    return InputError(SourceLocation(name_),
                      fmt::format("the zip is damaged: its entry \"{}\" cannot be inflated "
                                  "(a file cut short, or a wrong checksum); export it again",
                                  entry));
  }

  Memory memory_;
  std::string name_;
  unzFile zip_ = nullptr;
};

bool ends_with(std::string_view s, std::string_view end) {
  return s.size() >= end.size() && s.substr(s.size() - end.size()) == end;
}

// Which instruments are read first when a zip holds several.
int preference(MeasurementFile kind) {
  switch (kind) {
    case MeasurementFile::kPhyphoxMagnetometer:
      return 0;
    case MeasurementFile::kPhyphoxAccelerometer:
    case MeasurementFile::kPhyphoxLinearAccelerometer:
      return 1;
    case MeasurementFile::kTracker:
    case MeasurementFile::kPositionTable:
      return 2;
    default:
      return -1;
  }
}

}  // namespace

ZipMeasurement measurement_in_zip(std::string_view bytes, const std::string& name) {
  Archive archive(bytes, name);
  std::optional<ZipMeasurement> best;
  std::vector<std::string> held;
  for (const std::string& entry : archive.names()) {
    const std::string lower = ascii_lower(entry);
    if (lower.rfind("meta/", 0) == 0 || ends_with(lower, "/")) continue;
    if (!ends_with(lower, ".csv") && !ends_with(lower, ".txt") && !ends_with(lower, ".tsv")) {
      held.push_back(fmt::format("\"{}\"", entry));
      continue;
    }
    std::string text = archive.text_of(entry);
    const RecognisedFile kind = recognise_measurement_file(text);
    const int rank = preference(kind.kind);
    held.push_back(fmt::format(
        "\"{}\" ({})", entry,
        kind.kind == MeasurementFile::kRigLog ? "no instrument the lab knows" : kind.instrument));
    if (rank >= 0 && (!best || rank < preference(best->kind.kind)))
      best = ZipMeasurement{entry, std::move(text), kind};
  }
  if (!best)
    throw InputError(
        SourceLocation(name),
        fmt::format(
            "expected a recording of the plate's oscillation in the zip (phyphox's "
            "magnetometer or accelerometer, Tracker's data, a position table), found {}; "
            "record with phyphox's \"Magnetometer\" beside the rig or \"Acceleration\" "
            "on the plate",
            held.empty() ? std::string("no entry") : fmt::format("{}", fmt::join(held, ", "))));
  return *best;
}

bool reads_zips() {
  return true;
}

}  // namespace fl
