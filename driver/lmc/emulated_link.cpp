#include "driver/lmc/emulated_link.hpp"

namespace mark::lmc {

EmulatedLink::EmulatedLink(BoardOptions board, std::string variant, bool virtual_clock)
    : board_(with_variant(board, variant)), loop_(board_), variant_(std::move(variant)), virtual_(virtual_clock) {
  if (virtual_) board_.start_virtual_clock();
  else board_.start_clock(1.0);
}

EmulatedLink::~EmulatedLink() { board_.stop_clock(); }

std::string EmulatedLink::name() const {
  return "emulated board (" + variant_ + ", " + (virtual_ ? "virtual time" : "real time") + ")";
}

}  // namespace mark::lmc
