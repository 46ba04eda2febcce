#include "lvslam/io/rosbag_recovery.h"

#include <bzlib.h>
#include <roslz4/lz4s.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam {

namespace {

// Record op codes of the ROS bag 2.0 format (wiki.ros.org/Bags/Format/2.0).
constexpr std::uint8_t kOpMessageData = 0x02;
constexpr std::uint8_t kOpChunk = 0x05;
constexpr std::uint8_t kOpConnection = 0x07;
constexpr char kMagic[] = "#ROSBAG V2.0\n";
// A chunk larger than this is taken as damage rather than decompressed
// (rosbag record writes 768 KiB chunks unless told otherwise).
constexpr std::uint64_t kMaxChunkBytes = std::uint64_t{1} << 28;

std::uint32_t readU32(const std::uint8_t* p) {
  std::uint32_t v = 0;
  std::memcpy(&v, p, 4);  // the format is little-endian, as is this platform (see scan_file.cc)
  return v;
}

using Fields = std::map<std::string, std::string>;

// "len name=value" fields of a record header; false when malformed.
bool parseFields(const std::uint8_t* p, std::size_t size, Fields& fields) {
  fields.clear();
  std::size_t pos = 0;
  while (pos < size) {
    if (size - pos < 4) return false;
    const std::uint32_t len = readU32(p + pos);
    pos += 4;
    if (len > size - pos) return false;
    const std::string field(reinterpret_cast<const char*>(p + pos), len);
    pos += len;
    const auto eq = field.find('=');
    if (eq == std::string::npos) return false;
    fields[field.substr(0, eq)] = field.substr(eq + 1);
  }
  return true;
}

std::optional<std::uint32_t> fieldU32(const Fields& fields, const std::string& name) {
  const auto it = fields.find(name);
  if (it == fields.end() || it->second.size() != 4) return std::nullopt;
  return readU32(reinterpret_cast<const std::uint8_t*>(it->second.data()));
}

// Room for more output, doubled each time up to `declared` (the size the
// chunk header claims): a corrupt header must not allocate gigabytes before
// the data show they decompress to that much. False when full at `declared`.
bool grow(std::vector<std::uint8_t>& out, std::size_t declared) {
  if (out.size() >= declared) return false;
  out.resize(std::min<std::size_t>(declared, std::max<std::size_t>(out.size() * 2, 1 << 16)));
  return true;
}

// LZ4 writes no more than 255 bytes per input byte (a match length extends
// by 255 a byte), so more than that is not allocated whatever the header claims.
constexpr std::size_t kLz4MaxRatio = 256;

// Decompresses as much of `in` as is intact into `out` (a cut-off chunk gives
// its first blocks); `whole` says whether the stream ended as it should.
// roslz4 keeps a block whose output does not fit and says ROSLZ4_OUTPUT_SMALL,
// so the output buffer is sized once, not grown.
void decompressLz4(std::vector<std::uint8_t>& in, std::size_t declared, std::vector<std::uint8_t>& out, bool& whole) {
  roslz4_stream stream{};
  whole = false;
  out.assign(std::min(declared, kLz4MaxRatio * in.size()), 0);
  if (roslz4_decompressStart(&stream) != ROSLZ4_OK) {
    out.clear();
    return;
  }
  stream.input_next = reinterpret_cast<char*>(in.data());
  stream.input_left = static_cast<int>(in.size());
  stream.output_next = reinterpret_cast<char*>(out.data());
  stream.output_left = static_cast<int>(out.size());
  int ret = ROSLZ4_OK;
  while (ret == ROSLZ4_OK && stream.input_left > 0 && stream.output_left > 0) ret = roslz4_decompress(&stream);
  if (ret == ROSLZ4_OK && stream.output_left == 0) ret = roslz4_decompress(&stream);  // reads the checksum
  whole = ret == ROSLZ4_STREAM_END;
  out.resize(out.size() - static_cast<std::size_t>(stream.output_left));
  roslz4_decompressEnd(&stream);
}

void decompressBz2(std::vector<std::uint8_t>& in, std::size_t declared, std::vector<std::uint8_t>& out, bool& whole) {
  bz_stream stream{};
  whole = false;
  out.clear();
  if (BZ2_bzDecompressInit(&stream, 0, 0) != BZ_OK) return;
  stream.next_in = reinterpret_cast<char*>(in.data());
  stream.avail_in = static_cast<unsigned>(in.size());
  std::size_t produced = 0;
  int ret = BZ_OK;
  while (ret == BZ_OK && stream.avail_in > 0 && grow(out, declared)) {
    stream.next_out = reinterpret_cast<char*>(out.data() + produced);
    stream.avail_out = static_cast<unsigned>(out.size() - produced);
    while (ret == BZ_OK && stream.avail_in > 0 && stream.avail_out > 0) ret = BZ2_bzDecompress(&stream);
    produced = out.size() - stream.avail_out;
  }
  whole = ret == BZ_STREAM_END;
  out.resize(produced);
  BZ2_bzDecompressEnd(&stream);
}

}  // namespace

BagRecordScanner::BagRecordScanner(const std::string& path) : path_(path), in_(path, std::ios::binary) {
  if (!in_) throw Error(path, "cannot open bag file");
  in_.seekg(0, std::ios::end);
  file_size_ = static_cast<std::uint64_t>(in_.tellg());
  in_.seekg(0);
  char magic[sizeof(kMagic) - 1] = {};
  if (!in_.read(magic, sizeof(magic)) || std::memcmp(magic, kMagic, sizeof(magic)) != 0)
    throw Error(path, "not a ROS1 bag of format 2.0 (no '#ROSBAG V2.0' line at the start)");
}

void BagRecordScanner::stop(const std::string& why) {
  if (damage_.empty()) damage_ = why;
  done_ = true;
  chunk_.clear();
  chunk_pos_ = 0;
}

// One record from the file. A chunk cut off at the end of the file is returned
// with the bytes there are; anything else cut off or malformed stops the scan.
bool BagRecordScanner::readRecord(std::vector<std::uint8_t>& header, std::vector<std::uint8_t>& data) {
  const std::uint64_t start = static_cast<std::uint64_t>(in_.tellg());
  record_start_ = start;
  if (start == file_size_) {
    done_ = true;
    return false;
  }
  std::uint8_t len[4];
  if (!in_.read(reinterpret_cast<char*>(len), 4) || readU32(len) > file_size_ - start - 4) {
    stop(fmt::format("file cut off in the record header at byte {} of {}", start, file_size_));
    return false;
  }
  header.resize(readU32(len));
  if (!in_.read(reinterpret_cast<char*>(header.data()), static_cast<std::streamsize>(header.size())) ||
      !in_.read(reinterpret_cast<char*>(len), 4)) {
    stop(fmt::format("file cut off in the record header at byte {} of {}", start, file_size_));
    return false;
  }
  const std::uint64_t here = static_cast<std::uint64_t>(in_.tellg());
  const std::uint64_t available = file_size_ - here;
  data.resize(static_cast<std::size_t>(std::min<std::uint64_t>(readU32(len), available)));
  if (!in_.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size()))) {
    stop(fmt::format("read failed at byte {}", here));
    return false;
  }
  if (readU32(len) > available)
    damage_ = fmt::format("file cut off at byte {} inside the record that starts at byte {} ({} of its {} data bytes present)",
                          file_size_, start, available, readU32(len));
  return true;
}

bool BagRecordScanner::loadChunk(const std::vector<std::uint8_t>& header, std::vector<std::uint8_t>& data) {
  Fields fields;
  parseFields(header.data(), header.size(), fields);
  const auto size = fieldU32(fields, "size");
  const std::string compression = fields.count("compression") ? fields.at("compression") : "";
  if (!size || *size > kMaxChunkBytes) {
    stop("malformed chunk header");
    return false;
  }
  if (compression == "none") {
    chunk_ = std::move(data);
  } else if (compression == "lz4" || compression == "bz2") {
    bool whole = false;
    if (compression == "lz4")
      decompressLz4(data, *size, chunk_, whole);
    else
      decompressBz2(data, *size, chunk_, whole);
    // A whole chunk that does not decompress is damaged inside: none of its
    // messages can be trusted, so reading stops before it.
    if (!whole && damage_.empty()) {
      stop(fmt::format("the {} chunk at byte {} ({} bytes) is damaged: it does not decompress", compression,
                       record_start_, data.size()));
      return false;
    }
  } else {
    stop("unknown chunk compression '" + compression + "'");
    return false;
  }
  chunk_pos_ = 0;
  return true;
}

bool BagRecordScanner::handleRecord(const std::vector<std::uint8_t>& header, std::vector<std::uint8_t>& data,
                                    BagRecordMessage& message) {
  Fields fields;
  if (!parseFields(header.data(), header.size(), fields) || fields["op"].size() != 1) {
    stop("malformed record header");
    return false;
  }
  const auto op = static_cast<std::uint8_t>(fields["op"][0]);
  if (!damage_.empty() && op != kOpChunk && chunk_.empty()) {
    stop(damage_);  // only a chunk is of use when cut off
    return false;
  }
  if (op == kOpChunk) {
    loadChunk(header, data);
  } else if (op == kOpConnection) {
    Fields info;
    const auto conn = fieldU32(fields, "conn");
    if (conn && parseFields(data.data(), data.size(), info))
      connections_[*conn] = {fields["topic"], info["type"]};
  } else if (op == kOpMessageData) {
    const auto conn = fieldU32(fields, "conn");
    const auto it = fields.find("time");
    if (!conn || it == fields.end() || it->second.size() != 8) {
      stop("malformed message record");
      return false;
    }
    const auto* t = reinterpret_cast<const std::uint8_t*>(it->second.data());
    message.connection = *conn;
    message.time = static_cast<double>(readU32(t)) + 1e-9 * static_cast<double>(readU32(t + 4));
    message.data = std::move(data);
    return true;
  }
  return false;  // bag header, index and chunk info records carry no messages
}

std::optional<BagRecordMessage> BagRecordScanner::next() {
  std::vector<std::uint8_t> header, data;
  BagRecordMessage message;
  while (true) {
    if (chunk_pos_ < chunk_.size()) {
      // The records inside a decompressed chunk: connections and messages.
      const std::size_t left = chunk_.size() - chunk_pos_;
      const std::uint8_t* p = chunk_.data() + chunk_pos_;
      const std::uint32_t header_len = left >= 4 ? readU32(p) : 0;
      if (left < 8 || header_len > left - 8 || readU32(p + 4 + header_len) > left - 8 - header_len) {
        stop(damage_.empty() ? "malformed chunk: a record runs past its end" : damage_);
        return std::nullopt;
      }
      const std::uint32_t data_len = readU32(p + 4 + header_len);
      header.assign(p + 4, p + 4 + header_len);
      data.assign(p + 8 + header_len, p + 8 + header_len + data_len);
      chunk_pos_ += 8 + header_len + data_len;
      if (handleRecord(header, data, message)) return message;
      continue;
    }
    if (!damage_.empty()) stop(damage_);  // the cut-off chunk has been read
    if (done_ || !readRecord(header, data)) return std::nullopt;
    if (handleRecord(header, data, message)) return message;
  }
}

}  // namespace lvslam
