// Output that never loses a file: the result goes to a hidden temporary file
// in the output's folder, every write is checked, and only a complete,
// fsync'ed file is renamed over the target. On an error, a signal that stops
// the run (SIGINT, SIGTERM, SIGHUP, ...) or a crash, the temporary file is removed
// and an existing output is left untouched; after SIGKILL the target is
// untouched and at most the hidden temporary file `.NAME.XXXXXX` remains.
// A run with several outputs completes them all before it renames any, and
// renames them together, which a stopping signal cannot split.

#ifndef ENTROPY_SIMPLIFY_SAFE_OUTPUT_H
#define ENTROPY_SIMPLIFY_SAFE_OUTPUT_H

#include "byte_io.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace entropy_simplify {

// A file that cannot be written, or must not be: the message says why.
struct Output_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// The exit code of a run stopped by SIGINT, SIGTERM, SIGHUP or another
// stopping signal (see remove_output_on_signals).
constexpr int interrupted_exit_code = 130;

namespace safe_output_detail {

// The temporary files to remove when the run stops, one for each output of a
// run (the points, the indices of --indices, the picture of --render), with
// whether the outputs were committed. The thread that waits for the
// stopping signals takes the mutex before it reads them, so that it never
// sees a slot half written nor a group of renames half done. A crash handler
// reads them without the mutex, which it cannot take: the flags are atomic,
// and a slot's path is written before its flag is set.
inline constexpr int pending_slots = 3;
inline char pending_temporary[pending_slots][PATH_MAX];
inline std::atomic<bool> has_pending_temporary[pending_slots] = {};
inline std::mutex pending_mutex;
inline bool outputs_committed = false; // under pending_mutex

inline void remove_pending_temporary()
{
  for (int slot = 0; slot < pending_slots; ++slot)
    if (has_pending_temporary[slot].load())
      ::unlink(pending_temporary[slot]);
}

inline void say(const char* message) { [[maybe_unused]] const auto ignored = ::write(STDERR_FILENO, message, std::strlen(message)); }

// The signals whose default action ends the process and that a user or a
// system sends on purpose: a keyboard's Ctrl-C and Ctrl-\, kill, a closed
// terminal, timers, the user signals and the CPU-time limit. A signal the
// program was started with ignored (nohup, a shell's background job) stays
// ignored, as it would for any other program.
inline sigset_t stopping_signals()
{
  sigset_t set;
  sigemptyset(&set);
  for (int signal : { SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU, SIGVTALRM })
  {
    struct sigaction inherited = {};
    if (sigaction(signal, nullptr, &inherited) == 0 && inherited.sa_handler != SIG_IGN)
      sigaddset(&set, signal);
  }
  return set;
}

// The thread that handles the stopping signals, which every other thread
// blocks: in a thread of its own rather than in a handler, it takes the
// mutex like the rest of the program.
inline void wait_for_stopping_signal(sigset_t set)
{
  int signal = 0;
  while (sigwait(&set, &signal) != 0)
    continue;
  pending_mutex.lock(); // held until the process ends
  remove_pending_temporary();
  say(outputs_committed ? "entropy_simplify: interrupted after the output was written\n"
                        : "entropy_simplify: interrupted; no output was written\n");
  ::_exit(interrupted_exit_code);
}

// SIGBUS: the mapped input shrank, or its disk failed, while it was read.
// The others are defects: the run still crashes, but leaves no temporary file.
inline void remove_temporary_and_fail(int signal)
{
  remove_pending_temporary();
  if (signal == SIGBUS)
  {
    say("entropy_simplify: the input could not be read: it shrank, or its disk failed, while it was read; "
        "no output was written\n");
    ::_exit(1);
  }
  say("entropy_simplify: internal error (a crash); no output was written\n");
  // blocked while handled, the signal raised again ends the process on return
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

inline std::string reason(int error) { return std::strerror(error); }

} // namespace safe_output_detail

// Opens /dev/null on each standard descriptor the program was started with
// closed (`2>&-`): a file the program opens later would otherwise take its
// number, and what the program prints there, a note on stderr, would go
// into that file, an output among them. Call it before opening any file.
inline void keep_standard_descriptors_taken()
{
  for (int descriptor = STDIN_FILENO; descriptor <= STDERR_FILENO; ++descriptor)
    if (::fcntl(descriptor, F_GETFD) == -1 && errno == EBADF)
      // the lowest free number: this one, those below being open
      ::open("/dev/null", descriptor == STDIN_FILENO ? O_RDONLY : O_WRONLY);
}

// Makes the stopping signals (SIGINT, SIGTERM, SIGHUP and the others of
// stopping_signals, unless ignored from the start) remove the pending
// temporary files and exit with interrupted_exit_code, SIGBUS (an input that
// shrinks while mapped) and crashes remove them too, and SIGPIPE and SIGXFSZ
// harmless: a closed stderr makes writes to it fail, not the run, and a file
// size limit makes the write that crosses it fail with "File too large",
// which removes the temporary file like any failed write. Call it before any
// other thread starts: the threads started after it (TBB's workers) inherit
// the blocked stopping signals, which one thread of its own waits for.
inline void remove_output_on_signals()
{
  const sigset_t stopping = safe_output_detail::stopping_signals();
  pthread_sigmask(SIG_BLOCK, &stopping, nullptr);
  std::thread(safe_output_detail::wait_for_stopping_signal, stopping).detach();
  // a stack overflow leaves no stack to handle it on: give the handler its own
  static char alternate_stack[1 << 16];
  stack_t stack = {};
  stack.ss_sp = alternate_stack;
  stack.ss_size = sizeof alternate_stack;
  sigaltstack(&stack, nullptr);
  struct sigaction action = {};
  sigemptyset(&action.sa_mask);
  action.sa_handler = safe_output_detail::remove_temporary_and_fail;
  action.sa_flags = SA_ONSTACK;
  for (int signal : { SIGBUS, SIGSEGV, SIGFPE, SIGILL, SIGABRT })
    sigaction(signal, &action, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
}

// A sink writing to a file descriptor through a buffer, checking every
// write. The fault-injection seams, for the tests: when the environment
// variable ENTROPY_SIMPLIFY_TEST_FREE_BYTES is N, writes fail with ENOSPC
// once N bytes are written, as on a full disk; when
// ENTROPY_SIMPLIFY_TEST_STALL_AFTER_BYTES is N, the program stops for good
// once N bytes are written, as on a stuck disk, to be interrupted there.
class File_sink : public Sink
{
public:
  using Sink::write;

  File_sink(int descriptor, std::string name) : descriptor_(descriptor), name_(std::move(name))
  {
    buffer_.reserve(capacity);
    if (const char* free_bytes = std::getenv("ENTROPY_SIMPLIFY_TEST_FREE_BYTES"))
      free_bytes_ = std::strtoull(free_bytes, nullptr, 10);
    if (const char* stall = std::getenv("ENTROPY_SIMPLIFY_TEST_STALL_AFTER_BYTES"))
      stall_after_ = std::strtoull(stall, nullptr, 10);
  }

  void write(const char* data, std::size_t size) override
  {
    if (size > capacity - buffer_.size())
      flush();
    if (size >= capacity)
      write_all(data, size);
    else
      buffer_.insert(buffer_.end(), data, data + size);
  }

  void flush()
  {
    write_all(buffer_.data(), buffer_.size());
    buffer_.clear();
  }

private:
  static constexpr std::size_t capacity = std::size_t(1) << 20;

  void write_all(const char* data, std::size_t size)
  {
    while (size > 0)
    {
      const std::size_t allowed = (std::min)(size, free_bytes_);
      const ssize_t written = allowed == 0 ? (errno = ENOSPC, -1) : ::write(descriptor_, data, allowed);
      if (written < 0 && errno == EINTR)
        continue;
      if (written < 0)
        throw Output_error("cannot write '" + name_ + "': " + safe_output_detail::reason(errno));
      data += written;
      size -= std::size_t(written);
      free_bytes_ -= std::size_t(written);
      written_ += std::size_t(written);
      while (written_ >= stall_after_)
        ::pause();
    }
  }

  int descriptor_;
  std::string name_;
  std::vector<char> buffer_;
  std::size_t free_bytes_ = (std::numeric_limits<std::size_t>::max)();
  std::size_t stall_after_ = (std::numeric_limits<std::size_t>::max)();
  std::size_t written_ = 0;
};

// The output file of a run. Constructing it checks the target and creates
// the temporary file, so that a run fails before computing anything when it
// could not write its result; commit() puts the result in place.
class Safe_output
{
public:
  // Throws Output_error when `path` is the file `input_path` (by device and
  // inode, links followed), exists and is not a regular file, or when its
  // folder does not take a new file.
  Safe_output(const std::string& path, const std::string& input_path)
    : path_(path), target_(resolve_links(path)), mode_(mode_of_result(target_))
  {
    refuse_unsafe_target(input_path);
    refuse_long_name();
    create_temporary();
  }

  ~Safe_output()
  {
    if (descriptor_ >= 0)
      ::close(descriptor_);
    if (!committed_)
      discard_temporary();
  }

  Safe_output(const Safe_output&) = delete;
  Safe_output& operator=(const Safe_output&) = delete;

  Sink& sink() { return *sink_; }

  // Writes out what the sink holds and syncs it to the disk, where a full
  // disk shows, then closes the file.
  void complete()
  {
    if (completed_)
      return;
    sink_->flush();
    if (::fsync(descriptor_) != 0 || ::fchmod(descriptor_, mode_) != 0)
      throw Output_error("cannot write '" + path_ + "': " + safe_output_detail::reason(errno));
    const int descriptor = descriptor_;
    descriptor_ = -1;
    if (::close(descriptor) != 0)
      throw Output_error("cannot write '" + path_ + "': " + safe_output_detail::reason(errno));
    completed_ = true;
  }

  // Completes the file, and renames it over the target, which until then is
  // untouched.
  void commit();


private:
  friend void commit_together(std::initializer_list<Safe_output*> files);

  static std::string folder_of(const std::string& path)
  {
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  }

  static std::string name_of(const std::string& path)
  {
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
  }

  // A symbolic link is written through, to the file it names.
  static std::string resolve_links(const std::string& path)
  {
    struct stat link;
    if (::lstat(path.c_str(), &link) != 0 || !S_ISLNK(link.st_mode))
      return path;
    char resolved[PATH_MAX];
    if (::realpath(path.c_str(), resolved) == nullptr)
      throw Output_error("cannot write '" + path + "': it is a symbolic link to a missing file (" +
                         safe_output_detail::reason(errno) + ")");
    return resolved;
  }

  // A replaced file keeps its permissions; a new one gets the umask's.
  static mode_t mode_of_result(const std::string& target)
  {
    struct stat existing;
    if (::stat(target.c_str(), &existing) == 0)
      return existing.st_mode & 07777;
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
  }

  void refuse_unsafe_target(const std::string& input_path) const
  {
    struct stat output, input;
    if (::stat(target_.c_str(), &output) != 0)
      return;
    if (S_ISDIR(output.st_mode))
      throw Output_error("cannot write '" + path_ + "': it is a folder; give a file name");
    if (!S_ISREG(output.st_mode))
      throw Output_error("cannot write '" + path_ + "': it exists and is not a regular file (a device, a pipe "
                         "or a socket); give the name of a file");
    if (::stat(input_path.c_str(), &input) == 0 && input.st_dev == output.st_dev && input.st_ino == output.st_ino)
      throw Output_error("refusing to write '" + path_ + "': it is the input file '" + input_path +
                         "' (or a link to it), which would be lost; give another output file");
  }

  // A name the folder cannot hold would fail only at the rename, after the
  // computation: the temporary file's name is cut to fit, the target's is not.
  void refuse_long_name() const
  {
    const std::string name = name_of(target_);
    const long longest = ::pathconf(folder_of(target_).c_str(), _PC_NAME_MAX);
    if (longest > 0 && name.size() > std::size_t(longest))
      throw Output_error("cannot write '" + path_ + "': " + safe_output_detail::reason(ENAMETOOLONG) + " (" +
                         std::to_string(name.size()) + " characters; its folder takes names of up to " +
                         std::to_string(longest) + ")");
  }

  void create_temporary()
  {
    const std::string folder = folder_of(target_);
    // the temporary name adds 8 characters: cut a long name so that it stays
    // within the 255 a file name may have
    const std::string name = name_of(target_).substr(0, 200);
    std::string pattern = folder + "/." + name + ".XXXXXX";
    if (pattern.size() >= PATH_MAX)
      throw Output_error("cannot write '" + path_ + "': the path is too long");
    std::lock_guard<std::mutex> lock(safe_output_detail::pending_mutex);
    while (slot_ < safe_output_detail::pending_slots && safe_output_detail::has_pending_temporary[slot_].load())
      ++slot_;
    if (slot_ == safe_output_detail::pending_slots)
      throw std::logic_error("more outputs at once than the signal handlers can clean up");
    descriptor_ = ::mkstemp(pattern.data());
    if (descriptor_ < 0)
      throw Output_error("cannot write '" + path_ + "': " + safe_output_detail::reason(errno) +
                         " (creating a file in '" + folder + "')");
    temporary_ = pattern;
    std::memcpy(safe_output_detail::pending_temporary[slot_], pattern.c_str(), pattern.size() + 1);
    safe_output_detail::has_pending_temporary[slot_].store(true);
    try
    {
      sink_.reset(new File_sink(descriptor_, path_));
    }
    catch (...)
    {
      ::close(descriptor_);
      ::unlink(temporary_.c_str());
      safe_output_detail::has_pending_temporary[slot_].store(false);
      throw;
    }
  }

  void rename_over_target()
  {
    if (::rename(temporary_.c_str(), target_.c_str()) != 0)
      throw Output_error("cannot replace '" + path_ + "': " + safe_output_detail::reason(errno));
    safe_output_detail::has_pending_temporary[slot_].store(false);
    committed_ = true;
  }

  void discard_temporary()
  {
    if (temporary_.empty())
      return;
    std::lock_guard<std::mutex> lock(safe_output_detail::pending_mutex);
    ::unlink(temporary_.c_str());
    safe_output_detail::has_pending_temporary[slot_].store(false);
  }

  // The rename is durable once the folder is synced; the file itself is
  // complete either way, so a failure here loses nothing.
  void sync_folder() const
  {
    const int folder = ::open(folder_of(target_).c_str(), O_RDONLY | O_DIRECTORY);
    if (folder >= 0)
    {
      ::fsync(folder);
      ::close(folder);
    }
  }

  std::string path_, target_, temporary_;
  mode_t mode_;
  int descriptor_ = -1;
  int slot_ = 0; // in safe_output_detail::pending_temporary
  bool completed_ = false, committed_ = false;
  std::unique_ptr<File_sink> sink_;
};

// Completes the files (null ones skipped), then renames each over its
// target, which until then is untouched, the stopping signals held off until
// all are renamed. A failed rename (the folder made read-only meanwhile)
// stops there: the outputs before it are replaced, the others untouched.
inline void commit_together(std::initializer_list<Safe_output*> files)
{
  for (Safe_output* file : files)
    if (file)
      file->complete();
  {
    std::lock_guard<std::mutex> lock(safe_output_detail::pending_mutex);
    for (Safe_output* file : files)
      if (file)
        file->rename_over_target();
    safe_output_detail::outputs_committed = true;
  }
  for (Safe_output* file : files)
    if (file)
      file->sync_folder();
}

inline void Safe_output::commit() { commit_together({ this }); }

// Holds what the program prints on the standard output (a few kilobytes at
// most: the summary, a report, the help) until flush_standard_output writes
// it, so that a failed write comes with its reason. Call it before printing.
inline void buffer_standard_output()
{
  static char buffer[1 << 16]; // glibc sizes a buffer it allocates itself by the device, 4 KiB
  std::setvbuf(stdout, buffer, _IOFBF, sizeof buffer);
}

// Throws when what the program printed on the standard output (its summary,
// a report asked for, the help) did not all reach it: a report lost to a
// full disk or a closed pipe is a failure, as GNU's tools make it, and
// SIGPIPE, ignored, does not stop the run. `done`: what the message adds
// about the files.
inline void flush_standard_output(const std::string& done)
{
  errno = 0;
  if (std::fflush(stdout) == 0 && !std::ferror(stdout))
    return;
  const int error = errno;
  throw std::runtime_error("cannot write to the standard output" +
                           (error != 0 ? ": " + safe_output_detail::reason(error) : std::string()) + done);
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_SAFE_OUTPUT_H
