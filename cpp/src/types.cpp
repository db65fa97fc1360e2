// The names of the public enums of types.h, as the Python layer and the CLI print them.
#include "nonobtuse/types.h"

namespace nonobtuse {

const char* to_string(RefineStatus status) {
  switch (status) {
    case RefineStatus::Converged: return "converged";
    case RefineStatus::BudgetExhausted: return "budget_exhausted";
    case RefineStatus::MinLengthReached: return "min_length_reached";
    case RefineStatus::Stalled: return "stalled";
  }
  return "stalled";
}

}  // namespace nonobtuse
