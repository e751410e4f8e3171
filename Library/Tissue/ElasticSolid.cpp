#include "Tissue/ElasticSolid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace proxima
{
namespace
{
/// A 3x3 matrix by columns: what the deformation gradient F = sum_i x_i b_i^T is made of.
struct Matrix3
{
  Vec3 column[3];

  Vec3 operator*(const Vec3& v) const
  {
    return column[0] * v.x + column[1] * v.y + column[2] * v.z;
  }
  /// The transpose times `v`.
  Vec3 transposeTimes(const Vec3& v) const
  {
    return {dot(column[0], v), dot(column[1], v), dot(column[2], v)};
  }
};

/// The rotation of unit quaternion q = (w, x, y, z).
Matrix3 rotationOf(const std::array<double, 4>& q)
{
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Matrix3 r;
  r.column[0] = {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y)};
  r.column[1] = {2.0 * (x * y - w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + w * x)};
  r.column[2] = {2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y)};
  return r;
}

/// The rotation part of `a`, found from `q` by the fixed-point iteration of Muller, Bender,
/// Chentanez and Macklin ("A Robust Method to Extract the Rotational Part of Deformations",
/// 2016): turn R about (sum r_k x a_k) / |sum r_k . a_k| until that vanishes. Unlike a polar
/// decomposition it never divides by det(a), so an inverted or flat element still gets a
/// rotation. It converges linearly (faster the less the element is stretched): up to `maxTurns`
/// turns, stopping once a turn is below `settled` rad.
void extractRotation(const Matrix3& a, std::array<double, 4>& q, int maxTurns, double settled)
{
  for (int turn = 0; turn < maxTurns; ++turn)
  {
    const Matrix3 r = rotationOf(q);
    Vec3 numerator;
    double denominator = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      numerator = numerator + cross(r.column[k], a.column[k]);
      denominator += dot(r.column[k], a.column[k]);
    }
    const Vec3 omega = numerator / (std::fabs(denominator) + 1e-9);
    const double angle = norm(omega);
    if (angle < settled)
    {
      return;
    }
    // The turn as a quaternion: exact for a large angle; for a small one (every warm-started
    // step), (1, omega / 2), which the normalisation below makes a unit turn by the angle to
    // within angle^3 / 24, and costs no sine or cosine.
    double t[4] = {1.0, 0.5 * omega.x, 0.5 * omega.y, 0.5 * omega.z};
    if (angle > 0.1)
    {
      const Vec3 axis = omega / angle;
      const double s = std::sin(0.5 * angle);
      t[0] = std::cos(0.5 * angle);
      t[1] = axis.x * s;
      t[2] = axis.y * s;
      t[3] = axis.z * s;
    }
    // q <- t q
    const std::array<double, 4> turned{t[0] * q[0] - t[1] * q[1] - t[2] * q[2] - t[3] * q[3],
                                       t[0] * q[1] + t[1] * q[0] + t[2] * q[3] - t[3] * q[2],
                                       t[0] * q[2] - t[1] * q[3] + t[2] * q[0] + t[3] * q[1],
                                       t[0] * q[3] + t[1] * q[2] - t[2] * q[1] + t[3] * q[0]};
    const double length = std::sqrt(turned[0] * turned[0] + turned[1] * turned[1] +
                                    turned[2] * turned[2] + turned[3] * turned[3]);
    for (int i = 0; i < 4; ++i)
    {
      q[i] = turned[i] / length;
    }
  }
}

/// Hooke's law on displacement gradient g: sigma(g) b = lambda tr(g) b + mu (g + g^T) b.
Vec3 stressTimes(const Matrix3& g, double lambda, double mu, const Vec3& b)
{
  const double trace = g.column[0].x + g.column[1].y + g.column[2].z;
  return b * (lambda * trace) + (g * b + g.transposeTimes(b)) * mu;
}

/// A step's extraction: warm-started from the last step's rotation, at most this many turns, so
/// that a step's cost is fixed. A rotation left a little short (an element turning fast) is
/// finished by the next steps; the forces stay those of a rotated linear element, which is
/// stable whatever rotation it is given.
constexpr int kStepTurns = 3;
constexpr double kStepSettled = 1e-9; // rad
/// A placement's (setPositions, elasticEnergy): from any pose, converged.
constexpr int kFullTurns = 200;
constexpr double kFullSettled = 1e-13; // rad

Matrix3 cachedRotation(const std::array<Vec3, 3>& columns)
{
  return Matrix3{{columns[0], columns[1], columns[2]}};
}

/// sum_i value(i) b_i^T over an element's four corners: with the positions, the deformation
/// gradient F; with R^T times velocities or positions, the gradient without the rotation.
template <typename Value>
Matrix3 gradientOf(const std::array<Vec3, 4>& gradients, Value value)
{
  Matrix3 g;
  for (int i = 0; i < 4; ++i)
  {
    const Vec3 v = value(i);
    const Vec3& b = gradients[static_cast<std::size_t>(i)];
    g.column[0] = g.column[0] + v * b.x;
    g.column[1] = g.column[1] + v * b.y;
    g.column[2] = g.column[2] + v * b.z;
  }
  return g;
}

void require(bool condition, const std::string& what)
{
  if (!condition)
  {
    throw std::invalid_argument("ElasticSolid: " + what);
  }
}

} // namespace

ElasticSolid::ElasticSolid(const TetMesh& rest, const ElasticMaterial& material,
                           const ElasticSolidSettings& settings)
  : ElasticSolid(rest, std::vector<ElasticMaterial>(rest.tets.size(), material), settings)
{}

ElasticSolid::ElasticSolid(const TetMesh& rest, const std::vector<ElasticMaterial>& materials,
                           const ElasticSolidSettings& settings)
  : m_rest(rest)
  , m_settings(settings)
{
  require(!rest.tets.empty(), "the mesh has no tetrahedra");
  require(materials.size() == rest.tets.size(), "one material per tetrahedron is needed");
  require(std::isfinite(settings.density) && settings.density > 0.0, "density must be above 0");
  require(std::isfinite(settings.damping) && settings.damping >= 0.0, "damping must be 0 or more");
  require(std::isfinite(settings.timeStep) && settings.timeStep > 0.0,
          "the time step must be above 0");
  require(settings.solverIterations >= 1, "at least one solver iteration is needed");
  require(std::isfinite(settings.solverTolerance) && settings.solverTolerance >= 0.0,
          "the solver tolerance must be 0 or more");
  build(materials);
}

void ElasticSolid::build(const std::vector<ElasticMaterial>& materials)
{
  const std::size_t numVertices = m_rest.points.size();
  m_masses.assign(numVertices, 0.0);
  m_elements.reserve(m_rest.tets.size());
  for (std::size_t e = 0; e < m_rest.tets.size(); ++e)
  {
    const ElasticMaterial& material = materials[e];
    require(std::isfinite(material.youngsModulus) && material.youngsModulus > 0.0,
            "Young's modulus must be above 0");
    require(material.poissonRatio >= 0.0 && material.poissonRatio < 0.5,
            "Poisson's ratio must be in [0, 0.5)");
    Element element;
    element.vertices = m_rest.tets[e];
    for (const std::uint32_t v : element.vertices)
    {
      require(v < numVertices, "a tetrahedron names a vertex the mesh does not have");
    }
    const Vec3& x0 = m_rest.points[element.vertices[0]];
    const Vec3 d1 = m_rest.points[element.vertices[1]] - x0;
    const Vec3 d2 = m_rest.points[element.vertices[2]] - x0;
    const Vec3 d3 = m_rest.points[element.vertices[3]] - x0;
    const double determinant = dot(d1, cross(d2, d3));
    require(determinant > 0.0, "tetrahedron " + std::to_string(e) + " is inverted or flat");
    element.volume = determinant / 6.0;
    // The rows of Dm^-1 (Dm = [d1 d2 d3]) are the gradients of corners 1-3's barycentric
    // coordinates: cross products over the determinant.
    element.gradients[1] = cross(d2, d3) / determinant;
    element.gradients[2] = cross(d3, d1) / determinant;
    element.gradients[3] = cross(d1, d2) / determinant;
    element.gradients[0] = -(element.gradients[1] + element.gradients[2] + element.gradients[3]);
    const double e_ = material.youngsModulus;
    const double nu = material.poissonRatio;
    element.lambda = e_ * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    element.mu = e_ / (2.0 * (1.0 + nu));
    for (const std::uint32_t v : element.vertices)
    {
      m_masses[v] += 0.25 * m_settings.density * element.volume;
    }
    m_elements.push_back(element);
  }
  for (std::size_t v = 0; v < numVertices; ++v)
  {
    require(m_masses[v] > 0.0, "vertex " + std::to_string(v) + " belongs to no tetrahedron");
  }
  m_fixed.assign(numVertices, 0);
  m_positions = m_rest.points;
  m_velocities.assign(numVertices, Vec3{});
  m_externalForces.assign(numVertices, Vec3{});
  m_rhs.assign(numVertices, Vec3{});
  m_residual.assign(numVertices, Vec3{});
  m_direction.assign(numVertices, Vec3{});
  m_product.assign(numVertices, Vec3{});
  m_preconditioned.assign(numVertices, Vec3{});
  m_diagonal.assign(3 * numVertices, 0.0);
  buildBlockPattern();
}

void ElasticSolid::buildBlockPattern()
{
  const std::size_t numVertices = m_rest.points.size();
  std::vector<std::vector<std::uint32_t>> neighbours(numVertices);
  for (const Element& element : m_elements)
  {
    for (const std::uint32_t a : element.vertices)
    {
      for (const std::uint32_t b : element.vertices)
      {
        neighbours[a].push_back(b);
      }
    }
  }
  m_rowStart.assign(numVertices + 1, 0);
  m_blockColumns.clear();
  for (std::size_t i = 0; i < numVertices; ++i)
  {
    std::vector<std::uint32_t>& row = neighbours[i];
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    m_blockColumns.insert(m_blockColumns.end(), row.begin(), row.end());
    m_rowStart[i + 1] = static_cast<std::uint32_t>(m_blockColumns.size());
  }
  m_blocks.assign(9 * m_blockColumns.size(), 0.0);
  const auto blockOf = [&](std::uint32_t row, std::uint32_t column) {
    const auto first = m_blockColumns.begin() + m_rowStart[row];
    const auto last = m_blockColumns.begin() + m_rowStart[row + 1];
    return static_cast<std::uint32_t>(std::lower_bound(first, last, column) -
                                      m_blockColumns.begin());
  };
  m_elementBlocks.resize(m_elements.size());
  for (std::size_t e = 0; e < m_elements.size(); ++e)
  {
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        m_elementBlocks[e][static_cast<std::size_t>(4 * i + j)] =
          blockOf(m_elements[e].vertices[static_cast<std::size_t>(i)],
                  m_elements[e].vertices[static_cast<std::size_t>(j)]);
      }
    }
  }
  m_diagonalBlocks.resize(numVertices);
  for (std::uint32_t i = 0; i < numVertices; ++i)
  {
    m_diagonalBlocks[i] = blockOf(i, i);
  }
}

void ElasticSolid::assembleSystem()
{
  const double h = m_settings.timeStep;
  const double massScale = 1.0 + h * m_settings.damping;
  std::fill(m_blocks.begin(), m_blocks.end(), 0.0);
  for (std::size_t i = 0; i < m_diagonalBlocks.size(); ++i)
  {
    double* block = &m_blocks[9 * static_cast<std::size_t>(m_diagonalBlocks[i])];
    block[0] = block[4] = block[8] = massScale * m_masses[i];
  }
  for (std::size_t e = 0; e < m_elements.size(); ++e)
  {
    const Element& element = m_elements[e];
    const Matrix3 r = cachedRotation(element.rotationColumns);
    double rb[4][3];
    for (int i = 0; i < 4; ++i)
    {
      const Vec3 turned = r * element.gradients[static_cast<std::size_t>(i)];
      rb[i][0] = turned.x;
      rb[i][1] = turned.y;
      rb[i][2] = turned.z;
    }
    const double scale = h * h * element.volume;
    const double lambda = scale * element.lambda;
    const double mu = scale * element.mu;
    // Block (j, i) is block (i, j) transposed: each is made once.
    const std::array<std::uint32_t, 16>& where = m_elementBlocks[e];
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i; j < 4; ++j)
      {
        const double shear = mu * dot(element.gradients[static_cast<std::size_t>(i)],
                                      element.gradients[static_cast<std::size_t>(j)]);
        double block[9];
        for (int row = 0; row < 3; ++row)
        {
          for (int column = 0; column < 3; ++column)
          {
            block[3 * row + column] =
              lambda * rb[i][row] * rb[j][column] + mu * rb[j][row] * rb[i][column];
          }
          block[4 * row] += shear;
        }
        double* upper = &m_blocks[9 * static_cast<std::size_t>(where[4 * i + j])];
        for (int k = 0; k < 9; ++k)
        {
          upper[k] += block[k];
        }
        if (j != i)
        {
          double* lower = &m_blocks[9 * static_cast<std::size_t>(where[4 * j + i])];
          for (int row = 0; row < 3; ++row)
          {
            for (int column = 0; column < 3; ++column)
            {
              lower[3 * row + column] += block[3 * column + row];
            }
          }
        }
      }
    }
  }
  for (std::size_t i = 0; i < m_diagonalBlocks.size(); ++i)
  {
    const double* block = &m_blocks[9 * static_cast<std::size_t>(m_diagonalBlocks[i])];
    m_diagonal[3 * i] = block[0];
    m_diagonal[3 * i + 1] = block[4];
    m_diagonal[3 * i + 2] = block[8];
  }
}

void ElasticSolid::fixVertex(std::uint32_t vertex)
{
  m_fixed[vertex] = 1;
  m_velocities[vertex] = Vec3{};
}

void ElasticSolid::setPositions(const std::vector<Vec3>& positions)
{
  require(positions.size() == m_positions.size(), "one position per vertex is needed");
  m_positions = positions;
  for (std::size_t v = 0; v < m_velocities.size(); ++v)
  {
    m_velocities[v] = Vec3{};
  }
  // The rotations start again from none: the new pose may be far from the last one.
  for (Element& element : m_elements)
  {
    element.rotation = {1.0, 0.0, 0.0, 0.0};
  }
  updateRotations(true);
}

void ElasticSolid::setExternalForce(std::uint32_t vertex, const Vec3& force)
{
  m_externalForces[vertex] = force;
}

void ElasticSolid::clearExternalForces()
{
  for (Vec3& force : m_externalForces)
  {
    force = Vec3{};
  }
}

void ElasticSolid::updateRotations(bool converge)
{
  const int turns = converge ? kFullTurns : kStepTurns;
  const double settled = converge ? kFullSettled : kStepSettled;
  for (Element& element : m_elements)
  {
    const Matrix3 f =
      gradientOf(element.gradients, [&](int i) { return m_positions[element.vertices[i]]; });
    extractRotation(f, element.rotation, turns, settled);
    const Matrix3 r = rotationOf(element.rotation);
    element.rotationColumns = {r.column[0], r.column[1], r.column[2]};
  }
}

void ElasticSolid::addElasticForces(std::vector<Vec3>& forces) const
{
  for (const Element& element : m_elements)
  {
    const Matrix3 r = cachedRotation(element.rotationColumns);
    // g = R^T F - I: the displacement gradient with the rotation taken out.
    Matrix3 g = gradientOf(
      element.gradients, [&](int i) { return r.transposeTimes(m_positions[element.vertices[i]]); });
    g.column[0].x -= 1.0;
    g.column[1].y -= 1.0;
    g.column[2].z -= 1.0;
    for (int i = 0; i < 4; ++i)
    {
      const Vec3 local = stressTimes(g, element.lambda, element.mu, element.gradients[i]);
      forces[element.vertices[i]] = forces[element.vertices[i]] - r * local * element.volume;
    }
  }
}

void ElasticSolid::applySystem(const std::vector<Vec3>& v, std::vector<Vec3>& out) const
{
  const double h = m_settings.timeStep;
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    double x = 0.0, y = 0.0, z = 0.0;
    for (std::uint32_t k = m_rowStart[i]; k < m_rowStart[i + 1]; ++k)
    {
      const double* block = &m_blocks[9 * static_cast<std::size_t>(k)];
      const Vec3& u = v[m_blockColumns[k]];
      x += block[0] * u.x + block[1] * u.y + block[2] * u.z;
      y += block[3] * u.x + block[4] * u.y + block[5] * u.z;
      z += block[6] * u.x + block[7] * u.y + block[8] * u.z;
    }
    out[i] = Vec3{x, y, z};
  }
  for (int k = 0; k < m_numSprings; ++k)
  {
    const ContactSpring& spring = m_springs[k];
    double along = 0.0;
    for (int j = 0; j < 3; ++j)
    {
      along += spring.weights[j] * dot(spring.normal, v[spring.vertices[j]]);
    }
    const Vec3 push = spring.normal * (h * h * spring.stiffness * along);
    for (int j = 0; j < 3; ++j)
    {
      out[spring.vertices[j]] = out[spring.vertices[j]] + push * spring.weights[j];
    }
  }
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    if (m_fixed[i] != 0)
    {
      out[i] = Vec3{};
    }
  }
}

void ElasticSolid::setContactSprings(const ContactSpring* springs, int count)
{
  m_numSprings = 0;
  for (int k = 0; k < count && m_numSprings < kMaxContactSprings; ++k)
  {
    const ContactSpring& spring = springs[k];
    bool usable = std::isfinite(spring.stiffness) && spring.stiffness >= 0.0 &&
                  std::isfinite(spring.normal.x) && std::isfinite(spring.normal.y) &&
                  std::isfinite(spring.normal.z);
    for (int j = 0; j < 3 && usable; ++j)
    {
      usable = spring.vertices[j] < m_positions.size() && std::isfinite(spring.weights[j]);
    }
    if (usable)
    {
      m_springs[m_numSprings++] = spring;
    }
  }
}

void ElasticSolid::step()
{
  const double h = m_settings.timeStep;
  const std::size_t n = m_positions.size();
  updateRotations(false);

  // Right-hand side: M v + h (f_elastic(x) + f_external).
  for (std::size_t i = 0; i < n; ++i)
  {
    m_rhs[i] = m_externalForces[i];
  }
  addElasticForces(m_rhs);
  for (std::size_t i = 0; i < n; ++i)
  {
    m_rhs[i] = m_fixed[i] != 0 ? Vec3{} : m_velocities[i] * m_masses[i] + m_rhs[i] * h;
  }

  // The system, and its diagonal for the Jacobi preconditioner, with the springs' beside it.
  assembleSystem();
  for (int k = 0; k < m_numSprings; ++k)
  {
    const ContactSpring& spring = m_springs[k];
    const Vec3& normal = spring.normal;
    for (int j = 0; j < 3; ++j)
    {
      const double scale = h * h * spring.stiffness * spring.weights[j] * spring.weights[j];
      double* d = &m_diagonal[3 * spring.vertices[j]];
      d[0] += scale * normal.x * normal.x;
      d[1] += scale * normal.y * normal.y;
      d[2] += scale * normal.z * normal.z;
    }
  }
  const auto precondition = [&](const std::vector<Vec3>& in, std::vector<Vec3>& out) {
    for (std::size_t i = 0; i < n; ++i)
    {
      out[i] = m_fixed[i] != 0 ? Vec3{}
                               : Vec3{in[i].x / m_diagonal[3 * i], in[i].y / m_diagonal[3 * i + 1],
                                      in[i].z / m_diagonal[3 * i + 2]};
    }
  };
  const auto inner = [n](const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      sum += dot(a[i], b[i]);
    }
    return sum;
  };

  // Preconditioned conjugate gradients from the last velocities, a fixed number of iterations.
  applySystem(m_velocities, m_product);
  for (std::size_t i = 0; i < n; ++i)
  {
    m_residual[i] = m_rhs[i] - m_product[i];
  }
  precondition(m_residual, m_preconditioned);
  m_direction = m_preconditioned;
  double rz = inner(m_residual, m_preconditioned);
  const double rhsNorm = std::sqrt(inner(m_rhs, m_rhs));
  const double enough = m_settings.solverTolerance * rhsNorm;
  for (int iteration = 0; iteration < m_settings.solverIterations && rz > 0.0; ++iteration)
  {
    if (enough > 0.0 && std::sqrt(inner(m_residual, m_residual)) <= enough)
    {
      break;
    }
    applySystem(m_direction, m_product);
    const double curvature = inner(m_direction, m_product);
    if (!(curvature > 0.0))
    {
      break;
    }
    const double alpha = rz / curvature;
    for (std::size_t i = 0; i < n; ++i)
    {
      m_velocities[i] = m_velocities[i] + m_direction[i] * alpha;
      m_residual[i] = m_residual[i] - m_product[i] * alpha;
    }
    precondition(m_residual, m_preconditioned);
    const double next = inner(m_residual, m_preconditioned);
    const double beta = next / rz;
    rz = next;
    for (std::size_t i = 0; i < n; ++i)
    {
      m_direction[i] = m_preconditioned[i] + m_direction[i] * beta;
    }
  }
  m_lastResidual = rhsNorm > 0.0 ? std::sqrt(inner(m_residual, m_residual)) / rhsNorm : 0.0;

  for (std::size_t i = 0; i < n; ++i)
  {
    if (m_fixed[i] != 0)
    {
      m_velocities[i] = Vec3{};
    }
    m_positions[i] = m_positions[i] + m_velocities[i] * h;
  }
}

double ElasticSolid::maxDisplacement() const
{
  double largest = 0.0;
  for (std::size_t i = 0; i < m_positions.size(); ++i)
  {
    largest = std::max(largest, distance(m_positions[i], m_rest.points[i]));
  }
  return largest;
}

double ElasticSolid::kineticEnergy() const
{
  double energy = 0.0;
  for (std::size_t i = 0; i < m_velocities.size(); ++i)
  {
    energy += 0.5 * m_masses[i] * squaredNorm(m_velocities[i]);
  }
  return energy;
}

double ElasticSolid::elasticEnergy() const
{
  double energy = 0.0;
  for (const Element& element : m_elements)
  {
    const Matrix3 f =
      gradientOf(element.gradients, [&](int i) { return m_positions[element.vertices[i]]; });
    std::array<double, 4> q = element.rotation;
    extractRotation(f, q, kFullTurns, kFullSettled);
    const Matrix3 r = rotationOf(q);
    Matrix3 g;
    for (int k = 0; k < 3; ++k)
    {
      g.column[k] = r.transposeTimes(f.column[k]);
    }
    g.column[0].x -= 1.0;
    g.column[1].y -= 1.0;
    g.column[2].z -= 1.0;
    // W = V (mu eps:eps + lambda/2 tr(eps)^2), eps = (g + g^T) / 2.
    const double trace = g.column[0].x + g.column[1].y + g.column[2].z;
    const double e[3][3] = {
      {g.column[0].x, 0.5 * (g.column[1].x + g.column[0].y), 0.5 * (g.column[2].x + g.column[0].z)},
      {0.0, g.column[1].y, 0.5 * (g.column[2].y + g.column[1].z)},
      {0.0, 0.0, g.column[2].z}};
    const double epsilonSquared = e[0][0] * e[0][0] + e[1][1] * e[1][1] + e[2][2] * e[2][2] +
                                  2.0 * (e[0][1] * e[0][1] + e[0][2] * e[0][2] + e[1][2] * e[1][2]);
    energy += element.volume * (element.mu * epsilonSquared + 0.5 * element.lambda * trace * trace);
  }
  return energy;
}

} // namespace proxima
