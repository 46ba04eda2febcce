#pragma once
// Per-frame records kept on disk instead of in memory. A run's records grow
// with its length (a few kB per camera frame, in fused mode more than the
// whole visual map after a few minutes), while the online output never
// reads them again and the steps after the run read them in order. Each
// record is encoded field by field (record_fields.h) and appended to an
// anonymous file in the temporary directory, which vanishes with its last
// handle, also when the process dies. What stays in memory is 8 bytes a
// record (where it starts). One thread at a time may use a file. A record
// type's fields come from a `fields(archive, record)` that argument lookup
// finds where the file is used (record_fields.h lists the pipeline's).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/error.h"

namespace lvslam::system {

// Writes a record's fields into bytes.
class RecordWriter {
 public:
  template <typename T>
  void operator()(const T& value) {
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      raw(&value, sizeof(T));
    } else if constexpr (std::is_base_of_v<Eigen::MatrixBase<T>, T>) {
      static_assert(T::SizeAtCompileTime > 0, "fixed-size matrices only");
      raw(value.data(), sizeof(typename T::Scalar) * T::SizeAtCompileTime);
    } else if constexpr (std::is_same_v<T, Eigen::Isometry3d>) {
      (*this)(value.matrix());
    } else {
      fields(*this, const_cast<T&>(value));  // the writer only reads: see record_fields.h
    }
  }
  template <typename T>
  void operator()(const std::optional<T>& value) {
    (*this)(value.has_value());
    if (value) (*this)(*value);
  }
  template <typename T>
  void operator()(const std::vector<T>& items) {
    (*this)(static_cast<std::uint64_t>(items.size()));
    for (const T& item : items) (*this)(item);
  }
  template <typename T, std::size_t N>
  void operator()(const std::array<T, N>& items) {
    for (const T& item : items) (*this)(item);
  }
  void operator()(const std::string& text) {
    (*this)(static_cast<std::uint64_t>(text.size()));
    raw(text.data(), text.size());
  }
  const std::string& bytes() const { return bytes_; }

 private:
  void raw(const void* data, std::size_t size) { bytes_.append(static_cast<const char*>(data), size); }
  std::string bytes_;
};

// Reads them back, in the same order.
class RecordReader {
 public:
  explicit RecordReader(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  void operator()(T& value) {
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      raw(&value, sizeof(T));
    } else if constexpr (std::is_base_of_v<Eigen::MatrixBase<T>, T>) {
      raw(value.data(), sizeof(typename T::Scalar) * T::SizeAtCompileTime);
    } else if constexpr (std::is_same_v<T, Eigen::Isometry3d>) {
      (*this)(value.matrix());
    } else {
      fields(*this, value);
    }
  }
  template <typename T>
  void operator()(std::optional<T>& value) {
    bool present = false;
    (*this)(present);
    value.reset();
    if (present) (*this)(value.emplace());
  }
  // Item by item: a damaged count runs out of bytes before it can ask for
  // more memory than the items read so far take.
  template <typename T>
  void operator()(std::vector<T>& items) {
    const std::size_t n = count();
    items.clear();
    items.reserve(std::min<std::size_t>(n, 4096));
    for (std::size_t i = 0; i < n; ++i) (*this)(items.emplace_back());
  }
  template <typename T, std::size_t N>
  void operator()(std::array<T, N>& items) {
    for (T& item : items) (*this)(item);
  }
  void operator()(std::string& text) {
    text.assign(count(), '\0');
    raw(text.data(), text.size());
  }
  bool done() const { return bytes_.empty(); }

 private:
  std::size_t count() {
    std::uint64_t n = 0;
    (*this)(n);
    if (n > bytes_.size()) throw Error("record file", "a record is cut short");  // each item takes a byte at least
    return static_cast<std::size_t>(n);
  }
  void raw(void* data, std::size_t size) {
    if (size > bytes_.size()) throw Error("record file", "a record is cut short");
    std::memcpy(data, bytes_.data(), size);
    bytes_.remove_prefix(size);
  }
  std::string_view bytes_;
};

// An anonymous temporary file that bytes are appended to and read back from.
class SpoolFile {
 public:
  SpoolFile();  // throws lvslam::Error naming the directory when none can be made
  ~SpoolFile();
  SpoolFile(const SpoolFile&) = delete;
  SpoolFile& operator=(const SpoolFile&) = delete;

  // Where the bytes start in the file.
  std::uint64_t append(std::string_view bytes);
  std::string read(std::uint64_t offset, std::size_t size) const;

 private:
  void flush() const;
  int fd_ = -1;
  std::string directory_;
  // Appended bytes are written in blocks; a read writes what is pending
  // first (what the file holds changes, not what a reader sees).
  mutable std::uint64_t written_ = 0;
  mutable std::string pending_;
};

// A sequence of records of type T on disk: appended, read by index or in
// order. Reading gives copies (const, so that changing one does not
// compile); a record is changed by rewriting the file (update). A copy of
// the sequence is a new file.
template <typename T>
class RecordFile {
 public:
  RecordFile() = default;
  RecordFile(RecordFile&&) noexcept = default;
  RecordFile& operator=(RecordFile&&) noexcept = default;
  RecordFile(const RecordFile& other) {
    for (const T& record : other) push_back(record);
  }
  RecordFile& operator=(const RecordFile& other) {
    if (this != &other) *this = RecordFile(other);
    return *this;
  }

  void push_back(const T& record) {
    RecordWriter writer;
    writer(record);
    if (!file_) file_ = std::make_unique<SpoolFile>();
    ends_.push_back(file_->append(writer.bytes()) + writer.bytes().size());
  }
  std::size_t size() const { return ends_.size(); }
  bool empty() const { return ends_.empty(); }
  const T operator[](std::size_t i) const {
    if (i >= ends_.size()) throw Error("record file", "record " + std::to_string(i) + " of " + std::to_string(size()));
    const std::uint64_t begin = i == 0 ? 0 : ends_[i - 1];
    const std::string bytes = file_->read(begin, static_cast<std::size_t>(ends_[i] - begin));
    RecordReader reader(bytes);
    T record{};
    reader(record);
    if (!reader.done()) throw Error("record file", "record " + std::to_string(i) + " is longer than its fields");
    return record;
  }
  const T back() const { return (*this)[size() - 1]; }
  // Record i, none past the end.
  std::optional<T> get(std::size_t i) const { return i < size() ? std::optional<T>((*this)[i]) : std::nullopt; }

  // Every record through `change`, in order.
  template <typename Change>
  void update(Change change) {
    RecordFile changed;
    for (std::size_t i = 0; i < size(); ++i) {
      T record = (*this)[i];
      change(record);
      changed.push_back(record);
    }
    *this = std::move(changed);
  }

  class const_iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = const T*;
    using reference = const T&;
    const_iterator(const RecordFile* file, std::size_t i) : file_(file), i_(i) {}
    const T& operator*() const {
      if (!current_) current_ = (*file_)[i_];
      return *current_;
    }
    const T* operator->() const { return &**this; }
    const_iterator& operator++() {
      ++i_;
      current_.reset();
      return *this;
    }
    bool operator==(const const_iterator& other) const { return i_ == other.i_; }
    bool operator!=(const const_iterator& other) const { return i_ != other.i_; }

   private:
    const RecordFile* file_;
    std::size_t i_;
    mutable std::optional<T> current_;
  };
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size()}; }

 private:
  std::unique_ptr<SpoolFile> file_;
  std::vector<std::uint64_t> ends_;  // record i spans [ends_[i - 1], ends_[i])
};

}  // namespace lvslam::system
