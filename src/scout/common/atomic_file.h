#ifndef SCOUT_COMMON_ATOMIC_FILE_H_
#define SCOUT_COMMON_ATOMIC_FILE_H_

#include <filesystem>
#include <functional>
#include <string>

namespace scout {

// Writes 'path' through 'write' into a temporary file beside it, then renames
// it into place, so readers never see a half-written file. If 'write' throws,
// the temporary file is removed and the exception propagates. Throws
// InputError when the directory is not writable.
void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& tmp)>& write);

// Same, for text content.
void WriteTextFileAtomically(const std::filesystem::path& path, const std::string& content);

}  // namespace scout

#endif  // SCOUT_COMMON_ATOMIC_FILE_H_
