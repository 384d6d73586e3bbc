#include "solvers/friction/alart_curnier.hpp"

namespace impactbench::solvers {

LocalVector alart_curnier(double mu, const AlartCurnierParameters& rho, const LocalVector& r,
                          const LocalVector& u, LocalMatrix* a, LocalMatrix* b) {
  return alart_curnier_detail::evaluate(mu, rho, r, u, a, b);
}

}  // namespace impactbench::solvers
