/*!
\ingroup PkgMLSProjectionConcepts
\cgalConcept

The concept `MLSFunctionSpace` describes a finite-dimensional family \f$\mathcal{F}\f$ of local
curves (\f$D = 2\f$) or surfaces (\f$D = 3\f$), placed in a local reference frame, onto which
points can be projected exactly: the closest-point projection \f$C_f(x)\f$ of the unified MLS
projection \f$\mathcal{P}_U\f$ (equation 6 of the paper). Its members may be graphs of smooth
functions (`Paraboloid_function_space`) or non-smooth sets such as fans of planar wedges
(`Wedge_fan_function_space`), whose creases and apexes the operator then reconstructs exactly.

Everything is in <em>frame coordinates</em>: a point \f$x \in \mathbb{R}^D\f$ whose first
\f$D-1\f$ coordinates lie in the frame's tangent hyperplane and whose last coordinate is the
height along the frame normal \f$e_D\f$. Every member contains the frame origin.

The operator calls `closest_point()` for every neighbour at every evaluation of its energy, and
its Levenberg-Marquardt optimiser differentiates the residuals numerically; hence the residual
is the <em>signed</em> distance, continuous across the surface, and `closest_point()` must be
fast (no heap allocation, fixed-size Eigen types), deterministic, and return finite values for
any finite input. A model is a small class, cheap to copy; all member functions are `const`
and thread-safe.

\cgalHasModel `CGAL::MLS::Plane_function_space<D>`
\cgalHasModel `CGAL::MLS::Paraboloid_function_space<D>`
\cgalHasModel `CGAL::MLS::Wedge_fan_function_space<D, N>`

\sa `CGAL::MLS::Closest_point<D>`
\sa `MLSGraphFunctionSpace`
*/
class MLSFunctionSpace
{
public:

/// \name Types and constants
/// @{

/// The ambient dimension \f$D\f$, 2 or 3.
static constexpr int ambient_dimension;

/// The number \f$P\f$ of parameters of a member (0 for the plane, 1 and 3 for the quadratic
/// spaces in 2D and 3D, 2 and \f$2N\f$ for the fans).
static constexpr int number_of_parameters;

/// The parameters of a member: `Eigen::Matrix<double, number_of_parameters, 1>`. Their
/// meaning is documented by each model. Any finite value is a valid member (the optimiser
/// moves them freely).
typedef unspecified_type Parameters;

/// @}

/// \name Operations
/// @{

/// A short name of the space, for messages and command-line options.
static const char* name();

/// The fewest neighbours a fit needs: the number of parameters of the member plus those of
/// the frame, for the models of this package.
static constexpr std::size_t minimum_number_of_points();

/// The member \f$f = 0\f$, whose closest-point projection is the orthogonal projection on the
/// frame's hyperplane (empty for `Plane_function_space`).
Parameters identity() const;

/// An initial member for the optimiser, from a weighted linear least-squares fit of the `n`
/// points `p[0..n-1]` (frame coordinates, `Eigen::Matrix<double, D, 1>`) with non-negative
/// weights `w[0..n-1]`. Terms that a move of the frame generates (offsets, and slopes for
/// the quadratic spaces) may be dropped. Must return finite parameters for any input.
Parameters fit(const Eigen::Matrix<double, D, 1>* p, const double* w, std::size_t n) const;

/// The closest point of `x` (frame coordinates) on the member `c`, with the unit normal
/// there (oriented "up", towards \f$+e_D\f$ for a graph; the normalised sum of the adjacent
/// faces' normals at a crease or apex), the signed distance (positive on the side of the
/// normal), and whether the point is on a feature, a crease or apex (with the crease direction
/// in 3D). See `CGAL::MLS::Closest_point<D>`.
CGAL::MLS::Closest_point<D> closest_point(const Parameters& c, const Eigen::Matrix<double, D, 1>& x) const;

/// @}

/// \name Optional operations
/// The operators detect these at compile time.
/// @{

/// Optional. The closest points `out[0..n-1]` of the `n` points `x[0..n-1]` on the member `c`
/// and, when `gradients` is not null, the derivatives `gradients[i]` of their signed distances
/// with respect to the parameters (by the envelope theorem, \f$-g \cdot \partial S/\partial c\f$ at
/// the closest point \f$S\f$, \f$g = (x - S)/d\f$). With it, the operators use an analytic Jacobian
/// and prepare the member once per evaluation; without it, forward differences.
void closest_points(const Parameters& c, const Eigen::Matrix<double, D, 1>* x, std::size_t n,
                    CGAL::MLS::Closest_point<D>* out, Parameters* gradients) const;

/// Optional. The closest point `cp` of `x` on the member `c`, as `closest_point(c, x)`, and the
/// derivatives of its position on the piece of the member that holds it: by the parameters in
/// `d_parameters`, by `x` in `d_point`. Returns false where they are one-sided (the closest
/// point moves onto another piece when `c` or `x` moves, e.g. at a fan's apex); the derivatives
/// are then unspecified. With it, the closest-point operators differentiate \f$C_{H,f}(r)\f$ exactly
/// where it returns true, and by central differences elsewhere and without it.
bool closest_point_derivatives(const Parameters& c, const Eigen::Matrix<double, D, 1>& x,
                               CGAL::MLS::Closest_point<D>& cp,
                               Eigen::Matrix<double, D, number_of_parameters>& d_parameters,
                               Eigen::Matrix<double, D, D>& d_point) const;

/// Optional, with the next two. A member prepared for many closest-point queries (what
/// `closest_point()` computes from the parameters before it looks at `x`).
typedef unspecified_type Prepared_member;

/// Optional. The member `c` prepared once for `closest_point(const Prepared_member&, x)`.
Prepared_member prepare_member(const Parameters& c) const;

/// Optional. The closest point of `x` on the prepared member `m`, the same as `closest_point(c,
/// x)` for the `c` that `m` was prepared from. With it, `MLS_implicit_function` prepares the
/// local fit of each seed once and evaluates it from there.
CGAL::MLS::Closest_point<D> closest_point(const Prepared_member& m, const Eigen::Matrix<double, D, 1>& x) const;

/// Optional. A dimensionless residual added to the energy, zero for the members the space
/// considers plausible at bandwidth `h` (the quadratic spaces bound the curvature).
double regularization(const Parameters& c, double h) const;

/// Optional (required by `Single_phase_projection`). The point of a graph above or below `x`.
CGAL::MLS::Closest_point<D> vertical_projection(const Parameters& c, const Eigen::Matrix<double, D, 1>& x) const;

/// Optional. `static constexpr bool has_sharp_features = true` asks the operators for starts at
/// creases and apices proposed by splitting the neighbourhood; `static constexpr bool
/// is_rotation_invariant = true` (the space is closed under rotations of the frame) lets them
/// optimise the frame origin only.
static constexpr bool has_sharp_features;

/// Optional, for spaces with sharp features. The member made of the `k` hyperplanes (2 or 3)
/// through the frame origin with unit normals `normals[0..k-1]` (frame coordinates, each oriented
/// so that the others' pieces lie behind it): the boundary of the intersection of the half-spaces
/// behind them, a crease or a corner with its apex at the origin. Returns false when the space
/// cannot represent it. With it, the starts at creases and apices begin from that member (exact
/// on noiseless data); without it, from `fit()`.
bool member_of_hyperplanes(const Eigen::Matrix<double, D, 1>* normals, int k, Parameters& c) const;

/// @}

}; /* end MLSFunctionSpace */
