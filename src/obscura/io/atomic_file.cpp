#include "obscura/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

#include "obscura/math/error.h"
#include "obscura/math/request_error.h"

namespace obscura {

namespace {

// A name in the target's directory, hidden, unique to this process and to this write:
// ".NAME.tmp-PID-N.EXT".
std::string temporary_path_for(const std::string& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path path(target);
  // (Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"." + std::string`.)
  std::string name(1, '.');
  name.append(path.stem().string()).append(".tmp-").append(std::to_string(getpid()));
  name.append("-").append(std::to_string(counter++)).append(path.extension().string());
  return (path.parent_path() / name).string();
}

std::string system_reason(int error) {
  return std::strerror(error);
}

const char* file_kind(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISDIR(mode)) return "a directory";
  return "not a regular file";
}

thread_local OutputTransaction* current_transaction = nullptr;

}  // namespace

OutputTransaction::OutputTransaction() : outer_(current_transaction) {
  current_transaction = this;
}

OutputTransaction::~OutputTransaction() {
  current_transaction = outer_;
  for (const Finished& file : finished_) ::unlink(file.temporary.c_str());
}

void OutputTransaction::commit() {
  current_transaction = outer_;
  std::vector<Finished> files = std::exchange(finished_, {});
  for (size_t i = 0; i < files.size(); ++i) {
    const Finished& file = files[i];
    try {
      check_replaceable_output(file.target);
      if (::rename(file.temporary.c_str(), file.target.c_str()) != 0)
        throw Error(file.target,
                    "cannot move the finished file into place: " + system_reason(errno));
    } catch (const Error&) {
      for (size_t j = i; j < files.size(); ++j) ::unlink(files[j].temporary.c_str());
      throw;
    }
  }
}

void check_replaceable_output(const std::string& target) {
  struct stat named;
  if (::stat(target.c_str(), &named) != 0 || S_ISREG(named.st_mode)) return;
  struct stat link;
  bool through_link = ::lstat(target.c_str(), &link) == 0 && S_ISLNK(link.st_mode);
  throw RequestError(target,
                     std::string(through_link ? "names (through a symbolic link) " : "is ") +
                         file_kind(named.st_mode) +
                         "; outputs only replace regular files or create new ones: "
                         "choose a file name");
}

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
  check_replaceable_output(target_);
  temporary_ = temporary_path_for(target_);
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0) throw Error(target_, "cannot open for writing: " + system_reason(errno));
}

AtomicFile::~AtomicFile() {
  if (!committed_) discard();
}

void AtomicFile::discard() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(temporary_.c_str());
}

void AtomicFile::fail(const std::string& what) {
  discard();
  committed_ = true;  // nothing left for the destructor to remove
  throw Error(target_, what);
}

void AtomicFile::write(std::span<const uint8_t> bytes) {
  if (fd_ < 0) throw Error(target_, "the file is already closed");
  const uint8_t* p = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    // A short write that makes no progress (n == 0) cannot be retried forever.
    if (n <= 0) fail("write failed: " + system_reason(n < 0 ? errno : EIO));
    p += n;
    left -= size_t(n);
  }
}

void AtomicFile::write(const std::string& text) {
  write(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
}

void AtomicFile::commit() {
  if (fd_ < 0) throw Error(target_, "the file is already closed");
  // Some file systems (NFS, quotas) report a full disk only when the data is flushed or the file
  // closed.
  if (::fsync(fd_) != 0 && errno != EINVAL && errno != EROFS)
    fail("write failed: " + system_reason(errno));
  struct stat replaced;
  if (::stat(target_.c_str(), &replaced) == 0 && S_ISREG(replaced.st_mode) &&
      ::fchmod(fd_, replaced.st_mode & 07777) != 0)
    fail("cannot keep the replaced file's permissions: " + system_reason(errno));
  int fd = std::exchange(fd_, -1);
  if (::close(fd) != 0) fail("write failed: " + system_reason(errno));
  // Checked again at the last moment: the path may have become a device or FIFO while writing.
  try {
    check_replaceable_output(target_);
  } catch (const Error&) {
    discard();
    committed_ = true;
    throw;
  }
  if (current_transaction != nullptr) {
    current_transaction->finished_.push_back({temporary_, target_});
    committed_ = true;  // the transaction removes or renames it now
    return;
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0)
    fail("cannot move the finished file into place: " + system_reason(errno));
  committed_ = true;
}

void write_file_atomically(const std::string& path, std::span<const uint8_t> bytes) {
  AtomicFile file(path);
  file.write(bytes);
  file.commit();
}

}  // namespace obscura
