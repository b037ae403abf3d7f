// Progress lines in logs: 0%, each quarter once, and 100% with a time, also from threads.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "tools/common/progress.h"

namespace {

int count_of(const std::string& s, const std::string& needle) {
  int n = 0;
  for (size_t at = s.find(needle); at != std::string::npos; at = s.find(needle, at + 1)) ++n;
  return n;
}

TEST(Progress, LinesModePrintsEachQuarterOnce) {
  testing::internal::CaptureStderr();
  {
    sb::tools::Progress p("stage", 1000, sb::tools::Progress::Mode::Lines);
    std::vector<std::thread> workers;
    for (int t = 0; t < 4; ++t)
      workers.emplace_back([&p] {
        for (int i = 0; i < 250; ++i) p.advance();
      });
    for (auto& w : workers) w.join();
    EXPECT_GE(p.finish(), 0.0);
  }
  const std::string out = testing::internal::GetCapturedStderr();
  EXPECT_EQ(count_of(out, "stage: 0%"), 1) << out;
  EXPECT_EQ(count_of(out, "stage: 25%"), 1) << out;
  EXPECT_EQ(count_of(out, "stage: 50%"), 1) << out;
  EXPECT_EQ(count_of(out, "stage: 75%"), 1) << out;
  EXPECT_EQ(count_of(out, "stage: 100% (1000/1000)"), 1) << out;
  // In order, whichever worker won which quarter.
  EXPECT_LT(out.find("stage: 0%"), out.find("stage: 25%")) << out;
  EXPECT_LT(out.find("stage: 25%"), out.find("stage: 50%")) << out;
  EXPECT_LT(out.find("stage: 50%"), out.find("stage: 75%")) << out;
  EXPECT_LT(out.find("stage: 75%"), out.find("stage: 100%")) << out;
  EXPECT_EQ(out.find('\r'), std::string::npos) << "log lines must not carry carriage returns";
}

TEST(Progress, QuietPrintsNothingAndZeroTotalIsSafe) {
  testing::internal::CaptureStderr();
  {
    sb::tools::Progress q("quiet", 10, sb::tools::Progress::Mode::Quiet);
    q.advance(10);
    sb::tools::Progress z("empty", 0, sb::tools::Progress::Mode::Quiet);
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
