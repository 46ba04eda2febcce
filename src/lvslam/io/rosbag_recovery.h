#pragma once
// Reads a ROS1 bag (format 2.0) record by record from the start of the file,
// without its index: for bags cut off while recording or copying, whose index
// (written last) is missing. Reads up to the damage: whole chunks, and the
// complete messages of a chunk cut off in the middle. Internal to io/.
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lvslam {

struct BagConnection {
  std::string topic;
  std::string type;
};

struct BagRecordMessage {
  std::uint32_t connection = 0;
  double time = 0.0;  // record time, seconds
  std::vector<std::uint8_t> data;
};

class BagRecordScanner {
 public:
  // Throws lvslam::Error(path, ...) when the file is not a ROS1 bag 2.0.
  explicit BagRecordScanner(const std::string& path);

  // The next message record in file order; none at the end or at the damage.
  std::optional<BagRecordMessage> next();

  // Connections seen so far (all of them, once next() has returned none).
  const std::map<std::uint32_t, BagConnection>& connections() const { return connections_; }
  // Why reading stopped before the end of the file ("" when it did not).
  const std::string& damage() const { return damage_; }

 private:
  bool readRecord(std::vector<std::uint8_t>& header, std::vector<std::uint8_t>& data);
  bool loadChunk(const std::vector<std::uint8_t>& header, std::vector<std::uint8_t>& data);
  // Handles one record of the file or a chunk; true when it is a message.
  bool handleRecord(const std::vector<std::uint8_t>& header, std::vector<std::uint8_t>& data,
                    BagRecordMessage& message);
  void stop(const std::string& why);

  std::string path_;
  std::ifstream in_;
  std::uint64_t file_size_ = 0;
  std::uint64_t record_start_ = 0;  // byte offset of the record last read from the file
  std::vector<std::uint8_t> chunk_;  // decompressed records of the current chunk
  std::size_t chunk_pos_ = 0;
  std::map<std::uint32_t, BagConnection> connections_;
  std::string damage_;
  bool done_ = false;
};

}  // namespace lvslam
