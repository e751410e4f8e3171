#include "Runtime/BudgetResidual.h"

namespace proxima
{

BudgetResidualProbe::BudgetResidualProbe(const CollisionScene& scene,
                                         const ProxyParameters& parameters)
{
  ProxyParameters unbudgeted = parameters;
  unbudgeted.tickBudgetIterations = 0;
  unbudgeted.tickBudgetSeconds = 0.0;
  m_solver.setScene(&scene, unbudgeted);
}

double BudgetResidualProbe::residual(const Vec3& start, const Vec3& finger, const Vec3& limitedEnd)
{
  m_solver.resetProxy(start);
  const ProxyTickResult settled = m_solver.update(finger);
  return distance(settled.proxy, limitedEnd);
}

} // namespace proxima
