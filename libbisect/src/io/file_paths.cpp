#include "io/file_paths.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "bisect/errors.hpp"

namespace bisect::io {
namespace {

bool is_directory(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// The folder a path lies in ("." for a bare name).
std::string parent_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// Why `path` cannot be opened for writing, from the errno of the failed open.
std::string open_failure(const std::string& path, int err) {
  if (is_directory(path)) return path + ": is a directory";
  if (err == ENOENT && !is_directory(parent_of(path)))
    return path + ": cannot write: the directory " + parent_of(path) + " does not exist";
  if (err == EACCES) return path + ": cannot write: permission denied";
  return path + ": cannot write: " + std::strerror(err);
}

// Removes what a failed write left, when it is an ordinary file; says whether it did.
bool remove_partial(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && std::remove(path.c_str()) == 0;
}

}  // namespace

void check_readable_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const int err = errno;
    if (err == EACCES) throw InputError(path + ": cannot be read: permission denied");
    throw InputError(path + ": cannot open the file (" + std::strerror(err) + ")");
  }
  if (S_ISDIR(st.st_mode)) throw InputError(path + ": is a directory");
  if (::access(path.c_str(), R_OK) != 0) {
    const int err = errno;
    if (err == EACCES) throw InputError(path + ": cannot be read: permission denied");
    throw InputError(path + ": cannot be read: " + std::strerror(err));
  }
}

void check_output_path(const std::string& path) {
  if (path.empty()) throw InputError("an output file name is empty");
  if (is_directory(path)) throw InputError(path + ": is a directory");
  if (!is_directory(parent_of(path)))
    throw InputError(path + ": cannot write: the directory " + parent_of(path) + " does not exist");
}

void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& write) {
  if (path.empty()) throw InputError("an output file name is empty");
  if (is_directory(path)) throw InputError(path + ": is a directory");
  std::ofstream out;
  errno = 0;
  out.open(path, std::ios::binary | std::ios::trunc);
  if (!out.is_open()) throw InputError(open_failure(path, errno));
  try {
    write(out);
  } catch (...) {
    out.close();
    remove_partial(path);
    throw;
  }
  // A full disk shows only when the buffer goes out: check after the flush and the close
  // (the close writes the last buffer and reports what the kernel said about it).
  // errno still holds the reason of a write that failed inside `write` (formatting into a
  // failed stream makes no system call).
  int err = out ? 0 : errno;
  if (!err) {
    errno = 0;
    out.flush();
    if (!out) err = errno;
  }
  if (!err) {
    errno = 0;
    out.close();
    if (out.fail()) err = errno;
  } else {
    out.close();
  }
  if (err || out.fail()) {
    const bool removed = remove_partial(path);
    throw InputError(path + ": write failed: " + std::strerror(err ? err : EIO) +
                     (removed ? "; the partial file was removed" : ""));
  }
}

}  // namespace bisect::io
