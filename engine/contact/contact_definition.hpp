#pragma once
/// What a deck asked for in contact (from AFFE_CHAR_MECA/CONTACT or
/// DEFI_CONTACT), in engine terms. Filled by commands/, read by engine/contact.
#include <string>
#include <vector>

namespace lunaster::engine {

/// Where the contact conditions live (discretisation.hpp, mortar_segments.hpp).
enum class ContactDiscretisation {
  NodeToSegment,      ///< one point per slave vertex (FORMULATION='DISCRETE')
  IntegrationPoints,  ///< the points of a rule on each slave cell (FORMULATION='CONTINUE')
  MortarSegments,     ///< one dual weighted-gap row per slave node (DEFI_CONT, APPARIEMENT='MORTAR')
};

/// How they are enforced: the law (contact_law.hpp).
enum class ContactEnforcement {
  AugmentedLagrangian,  ///< LAGS_C unknowns, active iff lambda + rho g < 0 (ALGO_CONT='STANDARD')
  ActiveSet,            ///< exact LAGS_C, an active set updated after each Newton (ALGO_CONT='CONTRAINTE')
  Complementarity,      ///< primal-dual active set held exactly by elimination (mortar 'LAGRANGIEN')
  Penalty,              ///< a pressure per gap (Pa/m), LAGS_C reported (ALGO_CONT='PENALISATION')
  Springs,              ///< a spring per slave node (N/m, discrete E_N), no LAGS_C (discrete 'PENALISATION')
};

/// A contact method: a discretisation times an enforcement. The six combinations the decks
/// offer are named below (contact_factory.hpp's table).
struct ContactMethod {
  ContactDiscretisation where = ContactDiscretisation::IntegrationPoints;
  ContactEnforcement how = ContactEnforcement::AugmentedLagrangian;

  friend bool operator==(const ContactMethod&, const ContactMethod&) = default;

  static const ContactMethod Continuous;         ///< FORMULATION='CONTINUE' (ALGO_CONT='STANDARD')
  static const ContactMethod ContinuousPenalty;  ///< FORMULATION='CONTINUE', ALGO_CONT='PENALISATION'
  static const ContactMethod DiscreteLagrange;   ///< METHODE='CONTRAINTE' / FORMULATION='DISCRETE', ALGO_CONT='CONTRAINTE'
  static const ContactMethod DiscretePenalty;    ///< METHODE='PENALISATION' / ALGO_CONT='PENALISATION'
  static const ContactMethod MortarLagrange;     ///< DEFI_CONT APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN'
  static const ContactMethod MortarPenalty;      ///< DEFI_CONT APPARIEMENT='MORTAR', ALGO_CONT='PENALISATION'
};
inline constexpr ContactMethod ContactMethod::Continuous{ContactDiscretisation::IntegrationPoints,
                                                         ContactEnforcement::AugmentedLagrangian};
inline constexpr ContactMethod ContactMethod::ContinuousPenalty{ContactDiscretisation::IntegrationPoints,
                                                                ContactEnforcement::Penalty};
inline constexpr ContactMethod ContactMethod::DiscreteLagrange{ContactDiscretisation::NodeToSegment,
                                                               ContactEnforcement::ActiveSet};
inline constexpr ContactMethod ContactMethod::DiscretePenalty{ContactDiscretisation::NodeToSegment,
                                                              ContactEnforcement::Springs};
inline constexpr ContactMethod ContactMethod::MortarLagrange{ContactDiscretisation::MortarSegments,
                                                             ContactEnforcement::Complementarity};
inline constexpr ContactMethod ContactMethod::MortarPenalty{ContactDiscretisation::MortarSegments,
                                                            ContactEnforcement::Penalty};

/// How Coulomb friction is enforced at the points of a point discretisation (coulomb_law.hpp).
enum class FrictionEnforcement {
  None,                 ///< frictionless (FROTTEMENT='SANS')
  AugmentedLagrangian,  ///< LAGS_F1[, LAGS_F2] semi-multipliers, stick exact (CONTINUE, ALGO_FROT='STANDARD')
  Penalty,              ///< an elastic stick stiffness with history (CONTINUE ALGO_FROT='PENALISATION'; DISCRETE E_T)
};

enum class IntegrationScheme { Auto, Gauss, Simpson, NewtonCotes, Nodes };
enum class ContactInit { No, Yes, Interpenetrated };
enum class FixedPointOrNewton { FixedPoint, Newton };
enum class GeometryUpdate { Automatic, Controlled, None };  ///< REAC_GEOM

/// One contact zone: a slave and a master surface (boundary cells).
struct ContactZone {
  std::vector<int> slave_cells;
  std::vector<int> master_cells;
  IntegrationScheme integration = IntegrationScheme::Auto;
  int integration_order = 0;     ///< ORDRE_INT; 0 = scheme default
  int sub_elements = 1;          ///< seed's SIMPSON1/2, NCOTES1/2 variants map here
  /// COEF_CONT / COEF_REGU_CONT: the augmented Lagrangian's rho; DEFI_CONT LAGRANGIEN's relative c.
  double coef_cont = 100.0;
  double coef_pena = 0.0;        ///< E_N or COEF_PENA_CONT; DEFI_CONT PENALISATION's COEF_CONT (Pa/m)
  ContactInit init = ContactInit::Interpenetrated;
  double tole_proj_ext = 0.5;    ///< TOLE_PROJ_EXT: accepted projection distance outside a master cell (reference units)
  double dist_mait = 0.0;        ///< DIST_MAIT: thickness added to the master surface (m, mortar)
  double dist_escl = 0.0;        ///< DIST_ESCL: thickness added to the slave surface (m, mortar)
  // ---- Coulomb friction (ContactDefinition::friction) ----
  double mu = 0.0;               ///< COULOMB: the friction coefficient (>= 0)
  /// COEF_FROT (augmented Lagrangian: relative, times E / h) or the stick stiffness (penalty:
  /// COEF_PENA_FROT, Pa/m; discrete E_T, N/m per node).
  double coef_frot = 1e-3;
  std::string slave_group, master_group;  ///< mesh group names, for messages (may be empty)
};

struct ContactDefinition {
  ContactMethod method = ContactMethod::Continuous;
  std::vector<ContactZone> zones;
  FixedPointOrNewton status_loop = FixedPointOrNewton::FixedPoint;  ///< ALGO_RESO_CONT
  FixedPointOrNewton geometry_loop = FixedPointOrNewton::FixedPoint;  ///< ALGO_RESO_GEOM
  GeometryUpdate reac_geom = GeometryUpdate::Automatic;
  int iter_cont_maxi = 30;
  /// When > 0, the status loop may take this many iterations per contact point instead of
  /// iter_cont_maxi (code_aster's ITER_CONT_MULT for the discrete formulation, whose active
  /// set adds or removes one point per iteration).
  int status_iterations_per_point = 0;
  int iter_geom_maxi = 10;
  int nb_iter_geom = 2;      ///< with REAC_GEOM='CONTROLE'
  double resi_geom = 0.01;
  FrictionEnforcement friction = FrictionEnforcement::None;  ///< FROTTEMENT='COULOMB' and its ALGO_FROT
  /// With friction: Newton converges only once the contact pressures (the friction bounds) moved
  /// by at most this much, relative to the largest, over its last iteration (RESI_FROT; <= 0: no
  /// such test).
  double resi_frot = 0.0;
  double modulus = 0.0;      ///< largest Young's modulus of the model (Pa; scales mortar's complementarity constant)
  /// AXIS model (2D, x = r): every surface measure is r dl per radian, as the AXIS elements'
  /// (integration-point and mortar weights, nodal tributary areas), so contact pressures stay
  /// pressures and contact forces are per radian like the model's nodal forces.
  bool axisymmetric = false;
};

}  // namespace lunaster::engine
