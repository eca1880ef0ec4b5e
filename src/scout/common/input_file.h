#ifndef SCOUT_COMMON_INPUT_FILE_H_
#define SCOUT_COMMON_INPUT_FILE_H_

#include <filesystem>
#include <string>

namespace scout {

// Throws InputError unless 'path' (after symbolic links) is a regular file:
// "<path>: is a directory; expected <what>", "... does not exist ...", or, for
// a pipe or device, "... is not a regular file ...". Streams opened on a
// directory fail only on the first read, with a message about the library's
// buffers; and Scout reads datasets more than once (format detection, then
// the replay), which a pipe cannot give.
void RequireRegularFile(const std::filesystem::path& path, const std::string& what);

}  // namespace scout

#endif  // SCOUT_COMMON_INPUT_FILE_H_
