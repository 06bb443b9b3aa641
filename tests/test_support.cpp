#include "tests/test_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace recoil::test {
namespace fs = std::filesystem;

fs::path source_path(const std::string& relative) { return fs::path(RECOIL_SOURCE_DIR) / relative; }

fs::path scratch_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("recoil_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Built by appends: GCC 12's -Wrestrict misfires on chained operator+ of
// short literals once inlined.
std::string shell_quote(const fs::path& path) {
  std::string out(1, '\'');
  out.append(path.string());
  out.push_back('\'');
  return out;
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_file(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

CommandResult run_recoil(const std::string& args, const std::string& environment) {
  static int counter = 0;
  const fs::path dir = scratch_dir("run_recoil_" + std::to_string(counter++));
  const fs::path out = dir / "stdout.txt";
  const fs::path err = dir / "stderr.txt";
  const std::string command = (environment.empty() ? "" : "env " + environment + " ") + "'" + RECOIL_BINARY + "' " +
                              args + " </dev/null >'" +
                              out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = file_bytes(out);
  result.err = file_bytes(err);
  return result;
}

}  // namespace recoil::test
