// Writes that never leave a half-written file: data goes to a temporary file beside the target,
// which is renamed over it only when complete. An interrupted run leaves the old file (or none).
#pragma once

#include <string>
#include <string_view>

namespace mirage {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();  // removes the temporary file if commit() was not reached
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Where the writer should put the data.
  const std::string& tempPath() const { return temp_path_; }
  // Renames the temporary file over the target. Throws RuntimeError on failure.
  void commit();

 private:
  std::string path_, temp_path_;
  bool committed_ = false;
};

// Writes `content` to `path` atomically.
void writeFileAtomic(const std::string& path, std::string_view content);

// Reads a whole file; throws InputError naming the file if it cannot be read.
std::string readFile(const std::string& path);

}  // namespace mirage
