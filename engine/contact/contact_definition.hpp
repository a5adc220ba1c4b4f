#pragma once
/// What a deck asked for in contact (from AFFE_CHAR_MECA/CONTACT or
/// DEFI_CONTACT), in engine terms. Filled by commands/, read by engine/contact.
#include <string>
#include <vector>

namespace lunaster::engine {

enum class ContactMethod {
  Continuous,        ///< FORMULATION='CONTINUE' (ALGO_CONT='STANDARD'): augmented Lagrangian, LAGS_C
  ContinuousPenalty, ///< FORMULATION='CONTINUE', ALGO_CONT='PENALISATION'
  DiscreteLagrange,  ///< METHODE='CONTRAINTE' / FORMULATION='DISCRETE', ALGO_CONT='CONTRAINTE'
  DiscretePenalty,   ///< METHODE='PENALISATION' / ALGO_CONT='PENALISATION'
  MortarLagrange,    ///< DEFI_CONT APPARIEMENT='MORTAR', ALGO_CONT='LAGRANGIEN' (mortar_problem.hpp)
  MortarPenalty,     ///< DEFI_CONT APPARIEMENT='MORTAR', ALGO_CONT='PENALISATION'
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
  double modulus = 0.0;      ///< largest Young's modulus of the model (Pa; scales mortar's complementarity constant)
  /// AXIS model (2D, x = r): every surface measure is r dl per radian, as the AXIS elements'
  /// (integration-point and mortar weights, nodal tributary areas), so contact pressures stay
  /// pressures and contact forces are per radian like the model's nodal forces.
  bool axisymmetric = false;
};

}  // namespace lunaster::engine
