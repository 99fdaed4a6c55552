// Opening files for the readers and writers, with one-line reasons a user can act on. A
// directory given as a file, a missing or unreadable path, a write that did not reach the disk:
// each becomes an InputError naming the path, never a stream exception or a silent success.
#pragma once
#include <functional>
#include <iosfwd>
#include <string>

namespace bisect::io {

// Throws InputError unless `path` names a file this process can read: "<path>: is a directory",
// "<path>: cannot be read: permission denied", "<path>: cannot open the file (No such file or
// directory)". Called by every reader before it opens its file (a directory opens as a stream
// and only fails on the first read, with libstdc++'s "basic_filebuf::underflow").
void check_readable_file(const std::string& path);

// Throws InputError when `path` cannot be an output file: "<path>: is a directory", "<path>:
// cannot write: the directory D does not exist". Checked before a long job, so that a wrong -o
// fails at once rather than after the meshing.
void check_output_path(const std::string& path);

// Writes `path` through `write` and makes sure every byte reached it: the stream is checked
// after it is flushed and closed. On any failure (the file cannot be opened, a write or the
// close fails, `write` throws) a partial regular file is removed, and InputError names the path
// and the system's reason ("<path>: write failed: No space left on device; nothing was kept").
// Not a regular file (/dev/full, a pipe) is left alone.
void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace bisect::io
