// Errors a user can act on (host only). A CaseError names the file, the line (0 when unknown), the key
// and says what would be valid; the CLI prints it as `file:line: key: message` and exits with status 2.
#pragma once
#include <stdexcept>
#include <string>

namespace impactsph {

class CaseError : public std::runtime_error {
 public:
  CaseError(std::string file, int line, std::string key, const std::string& message)
      : std::runtime_error(format(file, line, key, message)), file_(std::move(file)), line_(line), key_(std::move(key)) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& key, const std::string& message) {
    std::string s = file.empty() ? std::string("<case>") : file;
    if (line > 0) s += ":" + std::to_string(line);
    s += ": ";
    if (!key.empty()) s += key + ": ";
    return s + message;
  }
  std::string file_;
  int line_;
  std::string key_;
};

// A run that cannot go on (NaN, time-step collapse, energy blow-up); the message names the particle and
// the offending fields. The last good state has been written before this is thrown.
class DivergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace impactsph
