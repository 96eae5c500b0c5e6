// How a fuzz target tells the standalone driver what became of an input: "ok", or the message of the typed
// error it ended in. libFuzzer has no such channel (its coverage is the feedback); under it the sink stays
// unset and noting costs a branch. The driver counts distinct outcomes and keeps the inputs that reach a new
// one as bases for further mutation (standalone_driver.cpp).
#pragma once

#include <string>

namespace shadelab::fuzz {

inline void (*outcomeSink)(const std::string& outcome) = nullptr;

inline void noteOutcome(const std::string& outcome) {
    if (outcomeSink) outcomeSink(outcome);
}

}  // namespace shadelab::fuzz
