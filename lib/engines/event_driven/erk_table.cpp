#include "lib/engines/event_driven/erk_table.hpp"

#include <memory>
#include <stdexcept>

namespace impactbench::engines::event_driven {

ARKODE_ERKTableID arkode_erk_table(ErkPair pair) {
  switch (pair) {
    case ErkPair::kDormandPrince54:
      return ARKODE_DORMAND_PRINCE_7_4_5;
    case ErkPair::kVerner65:
      return ARKODE_VERNER_8_5_6;
    case ErkPair::kFehlberg87:
      return ARKODE_FEHLBERG_13_7_8;
  }
  throw std::invalid_argument("event-driven: unknown Runge-Kutta pair");
}

ButcherPair load_butcher_pair(ErkPair pair) {
  struct TableDeleter {
    void operator()(ARKodeButcherTableMem* table) const { ARKodeButcherTable_Free(table); }
  };
  const std::unique_ptr<ARKodeButcherTableMem, TableDeleter> table(
      ARKodeButcherTable_LoadERK(arkode_erk_table(pair)));
  if (!table || !table->d)
    throw std::runtime_error("ARKODE has no embedded table for this Runge-Kutta pair");
  const int s = table->stages;
  ButcherPair out;
  out.a.setZero(s, s);
  out.b.resize(s);
  out.c.resize(s);
  out.d.resize(s);
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < i; ++j) out.a(i, j) = table->A[i][j];
    out.b[i] = table->b[i];
    out.c[i] = table->c[i];
    out.d[i] = table->d[i];
  }
  out.order = table->q;
  out.embedding_order = table->p;
  out.first_same_as_last = out.c[s - 1] == 1.0 && out.a.row(s - 1).transpose() == out.b;
  if (pair == ErkPair::kDormandPrince54) {
    out.quartic_correction.setZero(s);
    out.quartic_correction << -12715105075.0 / 11282082432.0, 0.0, 87487479700.0 / 32700410799.0,
        -10690763975.0 / 1880347072.0, 701980252875.0 / 199316789632.0, -1453857185.0 / 822651844.0,
        69997945.0 / 29380423.0;
  }
  return out;
}

}  // namespace impactbench::engines::event_driven
