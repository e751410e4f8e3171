// A soft solid that deforms: co-rotational linear finite elements on a tetrahedral mesh (Muller
// and Gross, "Interactive Virtual Materials", 2004), stepped by implicit Euler. Each element's
// rotation is taken out before Hooke's law is applied, so large rotations cost no ghost forces
// while the stiffness stays the linear one the closed forms of elasticity describe; implicit
// Euler damps rather than adds energy at any step (ElasticSolidTests measures it, since the
// rotations make the system nonlinear). The linear system of a step is solved with
// a fixed number of preconditioned conjugate-gradient iterations, warm-started from the last
// velocities: the cost of a step is the same every step, known before it runs, and step() does
// not allocate. Plain C++ like the kernel (Documentation/Tissue.md).
#pragma once

#include "Core/Vec3.h"
#include "Tissue/TetMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace proxima
{

/// An isotropic linear-elastic material.
struct ElasticMaterial
{
  /// Young's modulus (Pa): soft liver tissue is a few kPa, a stiff nodule tens of kPa.
  double youngsModulus = 3000.0;
  /// Poisson's ratio, in [0, 0.5): near 0.5 is nearly incompressible, as soft tissue is.
  double poissonRatio = 0.45;
};

/// How an ElasticSolid steps.
struct ElasticSolidSettings
{
  /// Mass density (kg/m^3); soft tissue is about that of water.
  double density = 1000.0;
  /// Mass-proportional damping (1/s): a free velocity decays as exp(-damping t).
  double damping = 1.0;
  /// The simulation's step (s).
  double timeStep = 0.005;
  /// Conjugate-gradient iterations per step: the most a step does, its designed cost. 20 leave a
  /// residual of about 2e-4 of the right-hand side on the kidney's 2,000 tetrahedra at 5 ms
  /// (BenchElasticStep).
  int solverIterations = 20;
  /// A step stops iterating early once the residual is below this fraction of the right-hand
  /// side; 0 (the default) always runs solverIterations, for a cost that is the same every step.
  double solverTolerance = 0.0;
};

/// A spring pressing on a point of the solid's surface along one direction: a proxy's contact
/// (TissueContact). The point is a weighted sum of three vertices (a surface triangle's corners
/// by the contact point's weights); the spring's force on it changes by -stiffness n n^T times
/// the point's motion.
struct ContactSpring
{
  /// The three vertices the point is made of.
  std::array<std::uint32_t, 3> vertices{};
  /// Their weights (barycentric: at least 0, summing to 1).
  std::array<double, 3> weights{};
  /// The unit direction the spring acts along.
  Vec3 normal;
  /// Its stiffness (N/m), at least 0.
  double stiffness = 0.0;
};

/// The most contact springs one step takes: a proxy's footprint of up to 512 triangles, each
/// held along three axes (TissueContact).
inline constexpr int kMaxContactSprings = 1536;

/// A tetrahedral solid with per-element stiffness, fixed vertices and external forces.
class ElasticSolid
{
public:
  /// The solid at rest in `rest` (positively oriented tetrahedra), of one material, or of one
  /// material per tetrahedron (`materials` as long as rest.tets). Throws std::invalid_argument for
  /// an empty mesh, an inverted or flat tetrahedron, a material out of range or settings that are
  /// not positive and finite.
  ElasticSolid(const TetMesh& rest, const ElasticMaterial& material,
               const ElasticSolidSettings& settings);
  /// The same with a material per tetrahedron.
  ElasticSolid(const TetMesh& rest, const std::vector<ElasticMaterial>& materials,
               const ElasticSolidSettings& settings);

  /// Holds vertex `vertex` where it is (a boundary condition): its velocity stays 0.
  void fixVertex(std::uint32_t vertex);
  /// Whether vertex `vertex` is held.
  bool isFixed(std::uint32_t vertex) const { return m_fixed[vertex] != 0; }

  /// Moves every vertex to `positions` (one per vertex, m) at rest: velocities 0. For placing the
  /// solid, or starting it deformed. Throws std::invalid_argument for a wrong count.
  void setPositions(const std::vector<Vec3>& positions);

  /// Sets the external force on `vertex` (N) until it is set again or cleared.
  void setExternalForce(std::uint32_t vertex, const Vec3& force);
  /// Sets every vertex's external force to 0.
  void clearExternalForces();
  /// The external force on `vertex` (N), as setExternalForce last set it.
  const Vec3& externalForce(std::uint32_t vertex) const { return m_externalForces[vertex]; }
  /// The springs the next steps take implicitly, beside the external forces (which hold their
  /// force at the current positions): their stiffness joins the elastic stiffness in the step's
  /// system, so that a stiff spring pressing a soft, light solid stays stable at the solid's step
  /// (with the force held explicitly, a 1000 N/m proxy spring threw a 5 kPa block's surface
  /// centimetres a step). At most kMaxContactSprings (more are ignored); vertices out of range
  /// and non-finite values are ignored too; `count` 0 clears them. Allocates nothing.
  void setContactSprings(const ContactSpring* springs, int count);
  /// The springs setContactSprings kept.
  int numContactSprings() const { return m_numSprings; }
  /// Spring `k` of those, below numContactSprings().
  const ContactSpring& contactSpring(int k) const { return m_springs[k]; }

  /// One implicit Euler step of settings().timeStep: no allocation, a fixed amount of work.
  void step();

  /// The vertices' current positions (m), in the rest mesh's order.
  const std::vector<Vec3>& positions() const { return m_positions; }
  /// The vertices' current velocities (m/s).
  const std::vector<Vec3>& velocities() const { return m_velocities; }
  /// The rest mesh.
  const TetMesh& rest() const { return m_rest; }
  /// The settings it steps with.
  const ElasticSolidSettings& settings() const { return m_settings; }
  /// Each vertex's lumped mass (kg).
  const std::vector<double>& masses() const { return m_masses; }

  /// Kinetic energy (J).
  double kineticEnergy() const;
  /// The largest distance of a vertex from its rest position (m). Allocates nothing.
  double maxDisplacement() const;
  /// Elastic energy (J): each element's linear strain energy of its rotation-free displacement,
  /// with the rotation extracted as step() extracts it.
  double elasticEnergy() const;
  /// The residual of the last step's linear system relative to its right-hand side, a measure of
  /// how far the fixed iterations left the solve from exact.
  double lastRelativeResidual() const { return m_lastResidual; }

private:
  struct Element
  {
    std::array<std::uint32_t, 4> vertices{};
    /// Shape-function gradients b_i (1/m) of the four corners at rest.
    std::array<Vec3, 4> gradients{};
    double volume = 0.0;
    double lambda = 0.0; ///< Lame's first parameter (Pa).
    double mu = 0.0;     ///< The shear modulus (Pa).
    /// The rotation from the last extraction, as a unit quaternion (w, x, y, z): the next
    /// extraction starts from it.
    std::array<double, 4> rotation{1.0, 0.0, 0.0, 0.0};
    /// The same rotation as a matrix's columns, made once per step for the solver's iterations.
    std::array<Vec3, 3> rotationColumns{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  };

  void build(const std::vector<ElasticMaterial>& materials);
  /// Each element's rotation from the current positions: a step's few turns, or converged.
  void updateRotations(bool converge);
  /// The block pattern of the system (a 3x3 block per vertex pair sharing a tetrahedron), and
  /// where each element's 16 corner pairs land in it: made once, by the constructor.
  void buildBlockPattern();
  /// The step's system (1 + h damping) M + h^2 K_rot into the blocks, and its diagonal into the
  /// Jacobi preconditioner; K_rot's blocks of an element are V (lambda Rb_i (Rb_j)^T
  /// + mu Rb_j (Rb_i)^T + mu b_i.b_j I).
  void assembleSystem();
  /// out = (1 + h damping) M v + h^2 (K_rot + K_springs) v, with fixed vertices' rows and columns
  /// left out.
  void applySystem(const std::vector<Vec3>& v, std::vector<Vec3>& out) const;
  /// The elastic forces at the current positions, added to `forces`.
  void addElasticForces(std::vector<Vec3>& forces) const;

  TetMesh m_rest;
  ElasticSolidSettings m_settings;
  std::vector<Element> m_elements;
  std::vector<double> m_masses;
  std::vector<char> m_fixed;
  std::vector<Vec3> m_positions;
  std::vector<Vec3> m_velocities;
  std::vector<Vec3> m_externalForces;
  std::vector<ContactSpring> m_springs = std::vector<ContactSpring>(kMaxContactSprings);
  int m_numSprings = 0;
  // The solver's work space, sized once: step() allocates nothing.
  std::vector<Vec3> m_rhs, m_residual, m_direction, m_product, m_preconditioned;
  std::vector<double> m_diagonal;
  // The system as 3x3 blocks by rows (compressed sparse rows of blocks): row i's blocks are
  // m_blocks[9 k ...] for k in [m_rowStart[i], m_rowStart[i + 1]), of columns m_blockColumns[k],
  // each stored by rows. Assembled once a step, it makes a solver iteration's product about a
  // tenth of the element-by-element one's work.
  std::vector<std::uint32_t> m_rowStart;
  std::vector<std::uint32_t> m_blockColumns;
  std::vector<double> m_blocks;
  /// Per element, the block of its corner pair (i, j) at [4 i + j].
  std::vector<std::array<std::uint32_t, 16>> m_elementBlocks;
  /// Per vertex, its diagonal block.
  std::vector<std::uint32_t> m_diagonalBlocks;
  double m_lastResidual = 0.0;
};

} // namespace proxima
