#pragma once
// InputError: bad user input. Carries where (file, line, column or key) and what was expected,
// so the CLI can print one clear message and exit with status 2.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace mpdem {

class InputError : public std::runtime_error {
 public:
  // line = 0 when unknown; key may name a TOML key ("time.dt") or a CSV column ("radius").
  InputError(std::string file, std::size_t line, std::string key, const std::string& message)
      : std::runtime_error(format(file, line, key, message)), file_(std::move(file)), line_(line),
        key_(std::move(key)) {}

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& key() const { return key_; }

 private:
  static std::string format(const std::string& file, std::size_t line, const std::string& key,
                            const std::string& message) {
    std::string s = file;
    if (line > 0) {
      s += ':';
      s += std::to_string(line);
    }
    // Without a file (an argument of a call, a command-line option) the message starts at the key.
    if (!key.empty()) s += (s.empty() ? "'" : ": '") + key + "'";
    return s.empty() ? message : s + ": " + message;
  }
  std::string file_;
  std::size_t line_;
  std::string key_;
};

}  // namespace mpdem
