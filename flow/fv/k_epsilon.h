#pragma once
// The k-epsilon models (doc/method.md, "Turbulence"): one step of
//   div(rho u k) = div((mu + mu_t/sigma_k) grad k) + P - rho epsilon [- D]
//   div(rho u e) = div((mu + mu_t/sigma_e) grad e) + C1 e/k P - C2 [f_2] rho e^2/k [+ E]
//   P = mu_t G,  G = 2 (u_x^2 + v_r^2 [+ (v/r)^2]) + (u_r + v_x)^2
// per outer iteration, then mu_t. The standard constants (Launder and Spalding 1974). Walls: k = 0;
// an inflow brings k = 3/2 (I u_n)^2, epsilon = C_mu^(3/4) k^(3/2)/L; an outflow, the axis and a
// symmetry plane take the cell's values. The sinks are implicit. KEpsilonModel holds what the
// variants share; each variant adds its wall treatment: the bracketed terms, the wall value of
// epsilon and its mu_t.
#include "flow/fv/turbulence_model.h"

#include <cmath>

namespace servodrift::flow
{
  namespace k_epsilon
  {
    constexpr double C_mu = 0.09, C1 = 1.44, C2 = 1.92, sigma_k = 1.0, sigma_epsilon = 1.3;
    /// A cell whose k is below this fraction of its neighbours' mean is a hole (D is linearised at
    /// that mean there). Measured on Launder-Sharma: the holes that held its developed pipe reached
    /// 1e-8 of their neighbours', and at 1e-6 the pipe still stalled; at 1e-4 the regression case's
    /// near-laminar orifice (40 degC, 1.03 MPa, mu_t/mu 0.016) fell to mu_t = 0 and stalled; at 1e-2
    /// cells of the impinging jet kept switching and it stalled.
    constexpr double hole_fraction = 1e-5;
  } // namespace k_epsilon

  class KEpsilonModel : public TurbulenceModel
  {
  public:
    KEpsilonModel(const FvMesh &mesh, const FluidProperties &fluid, const BoundaryConditions &boundaries,
                  const FlowSolverParameters &settings, const MatrixPattern &pattern);
    bool turbulent() const override { return true; }
    TurbulenceResiduals correct(const FlowState &state, const std::vector<double> &convecting_flux,
                                const TimeLevel *time = nullptr) override;
    /// k and epsilon
    std::vector<std::vector<double>> transported_fields() const override;
    void store(FlowFields &fields) const override;
    void restore(const FlowFields &fields) override;
    void scale_pressure_level(double s) override;
    std::vector<std::vector<double> *> accelerated_fields() override;
    void bound_accelerated(const std::vector<std::vector<double>> &before) override;
    std::vector<std::pair<std::string, const std::vector<double> *>> output_fields() const override;

  protected:
    /// The variant's boundary value of epsilon at a wall face of cell P.
    virtual double wall_epsilon(unsigned int P) const = 0;
    /// The variant's terms of this step, from the velocity gradients of the cells and the floors of
    /// k and epsilon: fills dissipation (the rate that sinks k), k_sink (D), epsilon_source (E) and
    /// destruction_factor (f_2).
    virtual void wall_terms(const std::vector<Vector2> &grad_u, const std::vector<Vector2> &grad_v, double k_floor,
                            double epsilon_floor) = 0;
    /// The variant's changes to the assembled, unrelaxed epsilon equation (a wall layer's epsilon).
    virtual void constrain_epsilon(FvMatrix &) {}
    /// The model's mu_t of cell c with the strain rate |S| (before the limit and the relaxation).
    virtual double model_viscosity(std::size_t c, double strain) const = 0;
    /// Whether the epsilon equation takes its terms from the state the k equation was linearised at
    /// (the iteration's start): the rate e/k from that k instead of the k just solved, and the
    /// production C1 e/k P with the model's mu_t of that state instead of the relaxed mu_t. The same
    /// at the fixed point, where the relaxed mu_t is the model's (at most the limit).
    virtual bool epsilon_terms_from_linearised_state() const { return false; }
    /// A turbulence time scale T of mu_t = rho C_mu k T under Durbin's realizability bound,
    /// min(T, a/(sqrt 6 C_mu |S|)) (a = `Realizability coefficient`, 0: no bound), at the strain rate |S|.
    double realizable_time_scale(double time_scale, double strain) const;
    /// Per cell, the mean of phi over the cells that share a face with it.
    std::vector<double> neighbour_mean(const std::vector<double> &phi) const;

    FlowSolverParameters settings;
    std::vector<double> k, epsilon;      ///< per cell: k [m^2/s^2], epsilon (e~ for Launder-Sharma) [m^2/s^3]
    std::vector<double> k_b, epsilon_b;  ///< per boundary face
    std::vector<double> dissipation, k_sink, epsilon_source, destruction_factor; ///< per cell, wall_terms()
    FvMatrix k_equation, epsilon_equation;
  };

  /// Standard k-epsilon with a two-layer wall treatment (the default): Wolfshtein's one-equation
  /// model with Chen and Patel's constants near walls, blended into the standard model by Jongen and
  /// Marx's function of Re_y = sqrt(k) y/nu; Durbin's realizability bound on the time scale.
  ///   mu_t = lambda rho C_mu k T + (1 - lambda) rho C_mu sqrt(k) l_mu,  T = min(k/e, a/(sqrt 6 C_mu |S|))
  ///   e = k^(3/2)/l_e imposed with the weight 1 - lambda,  l = C_l y (1 - exp(-Re_y/A)),
  /// lambda(Re_y) from 0 at the wall to 1 beyond Re_y = 60.
  class KEpsilonTwoLayer : public KEpsilonModel
  {
  public:
    KEpsilonTwoLayer(const FvMesh &mesh, const FluidProperties &fluid, const BoundaryConditions &boundaries,
                     const FlowSolverParameters &settings, const MatrixPattern &pattern);

  protected:
    double wall_epsilon(unsigned int P) const override { return epsilon[P]; }
    void wall_terms(const std::vector<Vector2> &grad_u, const std::vector<Vector2> &grad_v, double k_floor,
                    double epsilon_floor) override;
    void constrain_epsilon(FvMatrix &equation) override;
    double model_viscosity(std::size_t c, double strain) const override;

  private:
    std::vector<double> wall_distance; ///< per cell: to the nearest wall face [m]
    std::vector<double> layer_epsilon, layer_weight; ///< the one-equation model's epsilon and its weight 1 - lambda
  };

  /// Launder and Sharma's low-Reynolds-number k-epsilon: e is e~ (zero at walls),
  ///   mu_t = rho C_mu k T,  T = min(f_mu k/e~, a/(sqrt 6 C_mu |S|)) (Durbin's bound on mu_t, as above),
  ///   f_mu = exp(-3.4/(1 + Re_t/50)^2),  f_2 = 1 - 0.3 exp(-Re_t^2),
  ///   D = 2 mu |grad sqrt k|^2,  E = 2 mu nu_t |grad grad u|^2,  Re_t = rho k^2/(mu e~).
  class KEpsilonLaunderSharma : public KEpsilonModel
  {
  public:
    using KEpsilonModel::KEpsilonModel;

  protected:
    double wall_epsilon(unsigned int) const override { return 0; }
    /// Launder-Sharma's k just solved can fall below its floor in a cell where e~ is large (the
    /// nozzle bore's exit, a jet's edge); e~ over the floor then made that cell's e~ equation so
    /// stiff that its hot nozzle cases stalled and their marched steps hit the iteration cap. With
    /// e~/k from the linearised k but the production from the relaxed mu_t, 4 hot nozzle cases of
    /// its sweep were flagged 2; with the model's mu_t of the linearised state, 1 is (and without
    /// the hole rule, hole_fraction, its developed pipe stalled; doc/changes.md, issue 28:
    /// Launder-Sharma's e~ production and holes).
    /// The two-layer model keeps the k just solved and the relaxed mu_t: with the linearised k 14 of
    /// its default sweep's 10 and 20 um cases converged to other states (up to 4.8 % in C_d) and a
    /// coarse-mesh case stalled.
    bool epsilon_terms_from_linearised_state() const override { return true; }
    void wall_terms(const std::vector<Vector2> &grad_u, const std::vector<Vector2> &grad_v, double k_floor,
                    double epsilon_floor) override;
    double model_viscosity(std::size_t c, double strain) const override;
  };
} // namespace servodrift::flow
