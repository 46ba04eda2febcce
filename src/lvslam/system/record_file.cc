#include "lvslam/system/record_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace lvslam::system {

namespace {

constexpr std::size_t kWriteBlock = 1 << 16;

std::string systemError() { return std::strerror(errno); }

// O_TMPFILE: a file with no name at all; else a named one, unlinked at once.
int openAnonymousFile(const std::string& directory) {
#ifdef O_TMPFILE
  const int fd = ::open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) return fd;
#endif
  std::string name = directory + "/lvslam-records-XXXXXX";
  const int named = ::mkstemp(name.data());
  if (named >= 0) ::unlink(name.c_str());
  return named;
}

}  // namespace

SpoolFile::SpoolFile() {
  std::error_code ec;
  directory_ = std::filesystem::temp_directory_path(ec).string();
  if (ec) throw Error("record file", "no temporary directory (TMPDIR): " + ec.message());
  fd_ = openAnonymousFile(directory_);
  if (fd_ < 0) throw Error(directory_, "cannot make a temporary file for the run's records: " + systemError());
}

SpoolFile::~SpoolFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::uint64_t SpoolFile::append(std::string_view bytes) {
  const std::uint64_t offset = written_ + pending_.size();
  pending_.append(bytes);
  if (pending_.size() >= kWriteBlock) flush();
  return offset;
}

void SpoolFile::flush() const {
  std::size_t done = 0;
  while (done < pending_.size()) {
    const ssize_t n = ::pwrite(fd_, pending_.data() + done, pending_.size() - done,
                               static_cast<off_t>(written_ + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error(directory_, "cannot write the run's records to the temporary directory: " + systemError());
    done += static_cast<std::size_t>(n);
  }
  written_ += done;
  pending_.clear();
}

std::string SpoolFile::read(std::uint64_t offset, std::size_t size) const {
  if (offset + size > written_) flush();
  std::string bytes(size, '\0');
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::pread(fd_, bytes.data() + done, size - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error(directory_, "cannot read the run's records back from the temporary directory: " + systemError());
    done += static_cast<std::size_t>(n);
  }
  return bytes;
}

}  // namespace lvslam::system
