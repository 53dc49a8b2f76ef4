// libFuzzer target for `obscura color …`: the bytes are its arguments, one per line (at most 16),
// given to the same CLI11 parser and callbacks the command line runs (convert, wavelength,
// temperature, spaces). A CLI11 parse error, a UsageError or an obscura::Error is the expected
// outcome for bad arguments; anything else escaping, a crash or a sanitizer report is a finding.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "color_command.h"
#include "obscura/math/error.h"
#include "usage_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // `convert` with no values reads colours from stdin, and every command prints: give it an empty
  // stdin and a stdout that goes nowhere.
  static const bool quiet = [] {
    return std::freopen("/dev/null", "r", stdin) && std::freopen("/dev/null", "w", stdout);
  }();
  (void)quiet;

  std::vector<std::string> words{"obscura", "color"};
  std::string word;
  for (size_t i = 0; i < size && words.size() < 18; ++i) {
    char c = char(data[i]);
    if (c == '\n') {
      words.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty() && words.size() < 18) words.push_back(word);
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());

  CLI::App app("fuzz", "obscura");
  app.require_subcommand(1);
  obscura::app::add_color_command(app);
  try {
    app.parse(int(argv.size()), argv.data());
  } catch (const CLI::Error&) {
  } catch (const obscura::app::UsageError&) {
  } catch (const obscura::Error&) {
    // clear errors for bad arguments: the expected outcomes
  }
  return 0;
}
