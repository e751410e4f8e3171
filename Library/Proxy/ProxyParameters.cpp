#include "Proxy/ProxyParameters.h"

#include <algorithm>
#include <limits>

namespace proxima
{

double resolveSkin(const ProxyParameters& parameters, double diagonal, double maxAbsCoordinate)
{
  if (parameters.skin > 0.0)
  {
    return parameters.skin;
  }
  const double lengthScale = std::max(diagonal, parameters.radius);
  const double roundingScale = maxAbsCoordinate + lengthScale;
  return std::max(4e-12 * lengthScale,
                  256.0 * std::numeric_limits<double>::epsilon() * roundingScale);
}

} // namespace proxima
