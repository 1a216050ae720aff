// The input file, mapped read-only into memory: the readers parse it in
// place, so a 1 GB scan is not copied before it is parsed.

#ifndef ENTROPY_SIMPLIFY_INPUT_FILE_H
#define ENTROPY_SIMPLIFY_INPUT_FILE_H

#include "point_table.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <string_view>

namespace entropy_simplify {

class Input_file
{
public:
  // Throws Read_error, with the system's reason, when `path` cannot be
  // opened or is not a regular file.
  explicit Input_file(const std::string& path)
  {
    // O_NONBLOCK: opening a FIFO would otherwise wait for a writer
    const int descriptor = ::open(path.c_str(), O_RDONLY | O_NONBLOCK);
    if (descriptor < 0)
      throw Read_error(std::strerror(errno));
    struct stat status;
    if (::fstat(descriptor, &status) != 0 || !S_ISREG(status.st_mode))
    {
      const bool folder = S_ISDIR(status.st_mode);
      ::close(descriptor);
      throw Read_error(folder ? "it is a folder" : "it is not a regular file");
    }
    size_ = std::size_t(status.st_size);
    if (size_ > 0)
    {
      void* mapped = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, descriptor, 0);
      const int error = errno;
      ::close(descriptor);
      if (mapped == MAP_FAILED)
        throw Read_error(std::strerror(error));
      data_ = static_cast<const char*>(mapped);
    }
    else
      ::close(descriptor);
  }

  ~Input_file()
  {
    if (data_)
      ::munmap(const_cast<char*>(data_), size_);
  }

  Input_file(const Input_file&) = delete;
  Input_file& operator=(const Input_file&) = delete;

  std::string_view bytes() const { return { data_, size_ }; }

private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_INPUT_FILE_H
