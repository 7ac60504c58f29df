// Stop requests (common/interrupt.hpp): the flag, the exception's signal and exit code, and a real
// SIGTERM routed to the flag by the installed handler instead of ending the process.
#include <catch2/catch.hpp>
#include <csignal>

#include "common/interrupt.hpp"

using namespace coldblast::common;

TEST_CASE("a stop request is seen, thrown with its signal and cleared", "[fast]") {
  clear_stop();
  CHECK_FALSE(stop_requested());
  CHECK(stop_signal() == 0);
  CHECK_NOTHROW(throw_if_stop_requested());
  request_stop(SIGINT);
  CHECK(stop_requested());
  CHECK(stop_signal() == SIGINT);
  try {
    throw_if_stop_requested();
    FAIL("no exception");
  } catch (const Interrupted& e) {
    CHECK(e.signal() == SIGINT);
    CHECK(e.exit_code() == 130);
    CHECK(std::string(e.what()) == "interrupted by SIGINT");
  }
  clear_stop();
  CHECK_FALSE(stop_requested());
  CHECK(Interrupted(SIGTERM).exit_code() == 143);
}

TEST_CASE("the installed handler turns SIGTERM into a stop request", "[fast]") {
  clear_stop();
  install_stop_handlers();
  REQUIRE(std::raise(SIGTERM) == 0);  // with the default action this would end the test process
  CHECK(stop_requested());
  CHECK(stop_signal() == SIGTERM);
  clear_stop();
  std::signal(SIGTERM, SIG_DFL);
  std::signal(SIGINT, SIG_DFL);
}
