// The progress line's sink: a log line erases the status line first and redraws it after.
#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>
#include <string>

#include "run/status_line_sink.hpp"

namespace {

std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string out;
  for (int c; (c = std::fgetc(f)) != EOF;) out += static_cast<char>(c);
  return out;
}

}  // namespace

TEST(StatusLineSink, LogLinesStartCleanAndTheStatusLineComesBack) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  auto sink = std::make_shared<orogen::StatusLineSink>(f);
  spdlog::logger log("status_line_test", sink);
  log.set_pattern("%v");
  log.info("before");          // no status line yet: written as it is
  sink->show(" step 1");
  sink->show(" step 2");      // replaces the first
  log.info("output 1");
  sink->close();               // the last status line stays, the log goes on below it
  log.info("after");
  EXPECT_EQ(contents(f), "before\n step 1\r\033[K step 2\r\033[Koutput 1\n step 2\nafter\n");
  std::fclose(f);
}

TEST(StatusLineSink, WithoutAStatusLineItIsAPlainSink) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  auto sink = std::make_shared<orogen::StatusLineSink>(f);
  spdlog::logger log("status_line_plain", sink);
  log.set_pattern("%v");
  log.info("one");
  sink->close();
  log.info("two");
  EXPECT_EQ(contents(f), "one\ntwo\n");
  std::fclose(f);
}
