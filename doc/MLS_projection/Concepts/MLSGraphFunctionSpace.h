/*!
\ingroup PkgMLSProjectionConcepts
\cgalConcept

The concept `MLSGraphFunctionSpace` describes a finite-dimensional space \f$\mathcal{F}\f$ of
functions \f$f : \mathbb{R}^{D-1} \rightarrow \mathbb{R}\f$ whose graphs, placed in a local
reference frame, approximate an MLS curve (\f$D = 2\f$) or surface (\f$D = 3\f$) near a
query point. It is the function space of the second phase of Levin's projection
(equation 2 of the paper).

A frame is an origin \f$q\f$, a unit normal \f$n\f$ and an orthonormal basis
\f$t_1, \dots, t_{D-1}\f$ of the hyperplane orthogonal to \f$n\f$. The <em>frame
coordinates</em> of a point \f$p\f$ are \f$((p-q)\cdot t_1, \dots, (p-q)\cdot t_{D-1}, (p-q)\cdot n)\f$:
the first \f$D-1\f$ coordinates are the <em>domain point</em> \f$u\f$, the last one is the
<em>height</em> above the frame. The local curve or surface is the graph
\f$\{q + \sum_j u_j t_j + f(u)\,n\}\f$.

A model is a small class, cheap to copy, whose knobs (if any) are given to its constructor;
all member functions are `const` and thread-safe, since an operator calls them from
several threads at once.

\cgalHasModel `CGAL::MLS::Plane_function_space<D>`
\cgalHasModel `CGAL::MLS::Polynomial_function_space<D>`

\sa `CGAL::MLS::Levin_projection<GeomTraits, FunctionSpace>`
*/
class MLSGraphFunctionSpace
{
public:

/// \name Types and constants
/// @{

/// The ambient dimension \f$D\f$, 2 (curves) or 3 (surfaces). It sets the dimension of
/// the operator using the space.
static constexpr int ambient_dimension;

/// The number of parameters of a member of the space (0 for `Plane_function_space`,
/// 3 in 2D and 6 in 3D for `Polynomial_function_space`).
static constexpr int number_of_parameters;

/// The parameters of a member \f$f\f$: `Eigen::Matrix<double, number_of_parameters, 1>`.
/// The meaning of each coefficient is documented by the model; operators copy them into
/// `Projection_result::coefficients`.
typedef unspecified_type Parameters;

/// A point of the domain of \f$f\f$, in frame coordinates: `Eigen::Matrix<double, D-1, 1>`.
typedef unspecified_type Domain_point;

/// @}

/// \name Operations
/// @{

/// A short name of the space, for messages and command-line options (e.g. `"polynomial"`).
static const char* name();

/// The fewest neighbours a fit needs. Operators report `TOO_FEW_NEIGHBORS` when the
/// neighbourhood of a query holds fewer points (and never fewer than \f$D\f$).
static constexpr std::size_t minimum_number_of_points();

/// Returns the member of the space that fits the `n` points `p[0..n-1]`, given in frame
/// coordinates (`Eigen::Matrix<double, D, 1>`), with the non-negative weights `w[0..n-1]`,
/// in the weighted least-squares sense of equation 2: it minimises
/// \f$\sum_i w_i \, (p_{i,D} - f(p_{i,1..D-1}))^2\f$. Points of weight 0 are ignored.
/// Must return finite parameters for any input, including a neighbourhood that does not
/// determine every coefficient.
Parameters fit(const Eigen::Matrix<double, D, 1>* p, const double* w, std::size_t n) const;

/// The height \f$f(u)\f$ of the member with parameters `c` at the domain point `u`.
double height(const Parameters& c, const Domain_point& u) const;

/// The gradient \f$\nabla f(u)\f$, from which operators compute the normal
/// \f$n - \sum_j \partial_j f(u)\, t_j\f$ (normalised) of the result.
Domain_point gradient(const Parameters& c, const Domain_point& u) const;

/// @}

}; /* end MLSGraphFunctionSpace */
