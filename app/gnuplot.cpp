#include "app/gnuplot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "common/output.hpp"

namespace fs = std::filesystem;

namespace impactsph {

std::string gp_quote(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

std::string gp_number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream ss(path);
  std::string dir;
  while (std::getline(ss, dir, ':'))
    if (!dir.empty() && access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

std::string run_gnuplot(const fs::path& png, const std::function<std::string(const fs::path&)>& script_for) {
  if (!on_path("gnuplot"))
    return "gnuplot is not installed, so " + png.string() + " was not drawn. Install it with `sudo apt-get install "
           "gnuplot-nox`";
  const fs::path dir = png.parent_path().empty() ? fs::path(".") : png.parent_path();
  const fs::path tmp_name = png.filename().string() + ".tmp-" + std::to_string(getpid());
  const fs::path tmp = dir / tmp_name;
  const std::string script = "cd " + gp_quote(fs::absolute(dir).string()) + "\n" + script_for(tmp_name);
  void (*old_pipe)(int) = std::signal(SIGPIPE, SIG_IGN);  // gnuplot dying must not kill us mid-write
  FILE* pipe = popen("gnuplot", "w");
  if (!pipe) {
    std::signal(SIGPIPE, old_pipe);
    return "cannot start gnuplot: " + std::string(std::strerror(errno));
  }
  std::fwrite(script.data(), 1, script.size(), pipe);
  const int status = pclose(pipe);
  std::signal(SIGPIPE, old_pipe);
  std::error_code ec;
  if (status != 0 || !fs::exists(tmp) || fs::file_size(tmp, ec) == 0) {
    fs::remove(tmp, ec);
    return "gnuplot failed (" + (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                                   : std::string("killed")) +
           ") drawing " + png.string() + "; its messages are above";
  }
  fs::rename(tmp, png);
  return "";
}

std::string draw_gnuplot(const fs::path& png, const fs::path& gp_file,
                         const std::function<std::string(const fs::path&)>& script_for) {
  write_text_atomic(gp_file, script_for(png.filename()));
  const std::string error = run_gnuplot(png, script_for);
  if (error.empty()) return "";
  return error + ". The script is " + gp_file.string() + " (redraw it with `gnuplot " + gp_file.filename().string() +
         "` in its folder)";
}

}  // namespace impactsph
