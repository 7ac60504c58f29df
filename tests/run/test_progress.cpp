// Progress on stderr (run/progress.hpp): in a log (not a terminal) plain lines without a carriage
// return, one per tenth of the work or per 30 s, with the elapsed time and the ETA; on a terminal
// one line rewritten in place at most twice a second, ended by a newline.
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "run/progress.hpp"

using coldblast::run::Progress;

namespace {
/// What a Progress wrote into a temporary file.
std::string written(std::FILE* file) {
  std::fflush(file);
  std::rewind(file);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
  return text;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    out.push_back(text.substr(start, end - start));
  return out;
}
}  // namespace

TEST_CASE("progress in a log: a line per tenth of the work or per 30 s, no carriage return", "[fast]") {
  std::FILE* file = std::tmpfile();
  double now = 0.0;
  Progress progress("md run", "realizations", file, false, [&now] { return now; });
  CHECK_FALSE(progress.terminal());
  for (long long done = 1; done <= 1000; ++done) {
    now = 0.01 * static_cast<double>(done);  // 10 s in all: the tenths decide
    progress.update(done, 1000);
  }
  const std::string text = written(file);
  CHECK(text.find('\r') == std::string::npos);
  const std::vector<std::string> all = lines(text);
  REQUIRE(all.size() == 10);  // 10 %, 20 %, ..., 100 %
  CHECK(all.front() == "md run: 100/1000 realizations (10 %), 1.0 s elapsed, ETA 9.0 s");
  CHECK(all.back() == "md run: 1000/1000 realizations (100 %), 10.0 s elapsed, ETA 0.0 s");
  CHECK(text.back() == '\n');
  std::fclose(file);

  // A slow run: 3 units in 100 s print a line every 30 s as well, with the ETA in minutes.
  file = std::tmpfile();
  now = 0.0;
  Progress slow("tracer", "blocks", file, false, [&now] { return now; });
  slow.status("background");  // the first status is shown at once
  now = 30.0;
  slow.update(1, 1000);  // 0 %, but 30 s since the last line
  now = 45.0;
  slow.update(2, 1000);       // neither a new tenth nor 30 s: quiet
  slow.status("still here");  // 15 s after the last line: quiet
  now = 70.0;
  slow.status("block 3");  // 40 s: shown
  const std::vector<std::string> slow_lines = lines(written(file));
  REQUIRE(slow_lines.size() == 3);
  CHECK(slow_lines[0] == "tracer: background, 0.0 s elapsed");
  CHECK(slow_lines[1] == "tracer: 1/1000 blocks (0 %), 30.0 s elapsed, ETA 8.3 h");
  CHECK(slow_lines[2] == "tracer: block 3, 70.0 s elapsed");
  std::fclose(file);
}

TEST_CASE("progress on a terminal: one line rewritten in place at most twice a second", "[fast]") {
  std::FILE* file = std::tmpfile();
  double now = 0.0;
  Progress progress("md run", "realizations", file, true, [&now] { return now; });
  for (long long done = 1; done <= 80; ++done) {
    now = 0.125 * static_cast<double>(done);  // exact in binary: 4 updates make 0.5 s
    progress.update(done, 80);
  }
  const std::string text = written(file);
  std::size_t rewrites = 0;
  for (const char c : text) rewrites += c == '\r';
  CHECK(rewrites == 20);           // every 0.5 s of 10 s, the last included
  CHECK(lines(text).size() == 1);  // one newline, at the end
  CHECK(text.back() == '\n');
  CHECK(text.find("\rmd run: 80/80 realizations (100 %), 10.0 s elapsed, ETA 0.0 s   \n") != std::string::npos);
  std::fclose(file);
}
