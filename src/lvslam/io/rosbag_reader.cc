#include "lvslam/io/rosbag_reader.h"

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "lvslam/core/error.h"
#include "lvslam/io/rosbag_msgs.h"  // before rosbag: the C++20 allocator fix
#include "lvslam/io/rosbag_recovery.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>

namespace lvslam {

struct RosbagReader::Impl {
  std::string path;
  std::string damage;
  std::vector<BagTopicInfo> topics;
  double begin_time = 0.0, end_time = 0.0;
  std::set<std::string> selected;  // empty: all

  // Intact bags: rosbag_storage and its index.
  std::unique_ptr<rosbag::Bag> bag;
  std::unique_ptr<rosbag::View> view;
  rosbag::View::iterator it;

  // Damaged bags: a record scan from the start of the file.
  std::unique_ptr<BagRecordScanner> scanner;

  void openIndexed();
  void openRecovered(const std::string& index_error);
  std::optional<BagMessage> nextIndexed();
  std::optional<BagMessage> nextRecovered();
  std::string locateDamage() const;  // the damaged record's byte offset, by a scan of the file
};

void RosbagReader::Impl::openIndexed() {
  bag = std::make_unique<rosbag::Bag>(path, rosbag::bagmode::Read);
  rosbag::View all(*bag);
  std::map<std::string, BagTopicInfo> by_topic;
  for (const rosbag::ConnectionInfo* c : all.getConnections())
    by_topic[c->topic] = {c->topic, c->datatype, 0};
  for (auto& [name, info] : by_topic) info.messages = rosbag::View(*bag, rosbag::TopicQuery(name)).size();
  for (auto& [name, info] : by_topic) topics.push_back(info);
  if (all.size() > 0) {
    begin_time = rosmsg::toSeconds(all.getBeginTime());
    end_time = rosmsg::toSeconds(all.getEndTime());
  }
}

void RosbagReader::Impl::openRecovered(const std::string& index_error) {
  BagRecordScanner scan(path);  // throws when the file is not a bag at all
  std::map<std::uint32_t, std::size_t> counts;
  std::size_t total = 0;
  while (const auto m = scan.next()) {
    ++counts[m->connection];
    if (total++ == 0) begin_time = m->time;
    begin_time = std::min(begin_time, m->time);
    end_time = std::max(end_time, m->time);
  }
  damage = scan.damage().empty() ? "the bag index is unreadable (" + index_error + ")" : scan.damage();
  if (total == 0)
    throw Error(path, "damaged bag with no readable message: " + index_error + "; " + damage);
  std::map<std::string, BagTopicInfo> by_topic;
  for (const auto& [id, conn] : scan.connections()) {
    BagTopicInfo& info = by_topic[conn.topic];
    info.topic = conn.topic;
    info.type = conn.type;
    info.messages += counts[id];
  }
  for (auto& [name, info] : by_topic) topics.push_back(info);
}

std::optional<BagMessage> RosbagReader::Impl::nextIndexed() {
  if (!view || it == view->end()) return std::nullopt;
  // Topic and time come from the index; the data from a chunk, which may be damaged.
  const rosbag::MessageInstance& m = *it;
  BagMessage msg{m.getTopic(), m.getDataType(), rosmsg::toSeconds(m.getTime()), {}};
  try {
    msg.data.resize(m.size());
    ros::serialization::OStream stream(msg.data.data(), static_cast<std::uint32_t>(msg.data.size()));
    m.write(stream);
    ++it;
    return msg;
  } catch (const std::exception& e) {
    // A damaged chunk (ROSLZ4_DATA_ERROR, ...): read up to it, and say where.
    damage = fmt::format("the message of topic {} recorded at {:.6f} cannot be read ({}); {}", msg.topic,
                         msg.record_time, e.what(), locateDamage());
    spdlog::warn("{}: damaged bag, read up to the damage ({})", path, damage);
    view.reset();
    return std::nullopt;
  }
}

std::string RosbagReader::Impl::locateDamage() const {
  BagRecordScanner scan(path);
  while (scan.next()) {
  }
  return scan.damage().empty() ? "no damaged record found by a scan of the file" : scan.damage();
}

std::optional<BagMessage> RosbagReader::Impl::nextRecovered() {
  while (const auto m = scanner->next()) {
    const auto conn = scanner->connections().find(m->connection);
    if (conn == scanner->connections().end()) continue;  // its connection record was lost
    if (!selected.empty() && !selected.count(conn->second.topic)) continue;
    return BagMessage{conn->second.topic, conn->second.type, m->time, m->data};
  }
  return std::nullopt;
}

RosbagReader::RosbagReader(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  try {
    impl_->openIndexed();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    // rosbag_storage needs the index at the end of the file; without it, scan.
    impl_->bag.reset();
    impl_->topics.clear();
    impl_->openRecovered(e.what());
  }
  select({});
}

RosbagReader::~RosbagReader() = default;

const std::string& RosbagReader::path() const { return impl_->path; }
std::vector<BagTopicInfo> RosbagReader::topics() const { return impl_->topics; }
double RosbagReader::beginTime() const { return impl_->begin_time; }
double RosbagReader::endTime() const { return impl_->end_time; }
const std::string& RosbagReader::damage() const { return impl_->damage; }

std::optional<BagTopicInfo> RosbagReader::topic(const std::string& name) const {
  for (const auto& t : impl_->topics)
    if (t.topic == name) return t;
  return std::nullopt;
}

void RosbagReader::select(const std::vector<std::string>& topics) {
  impl_->selected = std::set<std::string>(topics.begin(), topics.end());
  try {
    if (impl_->bag) {
      impl_->view = topics.empty() ? std::make_unique<rosbag::View>(*impl_->bag)
                                   : std::make_unique<rosbag::View>(*impl_->bag, rosbag::TopicQuery(topics));
      impl_->it = impl_->view->begin();
    } else {
      impl_->scanner = std::make_unique<BagRecordScanner>(impl_->path);
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(impl_->path, std::string("cannot read the bag: ") + e.what());
  }
}

std::optional<BagMessage> RosbagReader::next() {
  return impl_->bag ? impl_->nextIndexed() : impl_->nextRecovered();
}

}  // namespace lvslam
