#pragma once
/// Coulomb friction as a point law (point_law.hpp) on top of a frictionless one: the normal
/// condition is the frictionless law's (its status set by the shared part's loops, held in the
/// point's state), the tangential ones are Coulomb's, decided at every evaluation from the
/// present iterate (semi-smooth Newton: code_aster's ALGO_RESO_FROT='NEWTON').
///
/// The normal force of a point is read from the frictionless law's response: N = -r_q[0] (N:
/// the force conjugate to the gap), the pressure p = N / w_t with w_t the point's weight, or 1
/// for nodal springs (discrete E_N: p is then the node's normal force, and the tangential
/// stiffness E_T a spring too). Its derivatives come with it (dp/dg = -k_qq/w_t, dp/dlambda =
/// -k_qz/w_t), so the tangent is consistent whatever the normal law. The slip ds is the
/// tangential relative displacement (x_slave - x_master along the point's tangents) since the
/// step's start; a positive tangential force on q resists a positive slip.
///
/// - Augmented Lagrangian (CONTINUE, ALGO_FROT='STANDARD', Alart and Curnier's): the multipliers
///   lambda_t (LAGS_F1[, LAGS_F2], the tangential traction, Pa). With v = lambda_t + c ds (c, Pa/m:
///   COEF_FROT E / h) and t = P(v) its projection on the disc of radius mu p: r_q,t = w_t t,
///   r_z,t = (w / c)(t - lambda_t). Stick (|v| <= mu p): ds = 0 exactly (the stick block is
///   symmetric); slip: lambda_t = mu p v / |v|, the bound along the slip. An open point: r_z,t =
///   -(w / c) lambda_t. code_aster's unknowns are the traction over mu p (|LAGS_F| <= 1): the
///   results report them so (contact_problem.cpp).
/// - Penalty (CONTINUE ALGO_FROT='PENALISATION', COEF_PENA_FROT in Pa/m; DISCRETE, E_T in N/m):
///   the trial traction t* = t_start + k ds (t_start: history, the traction at the step's start),
///   t = P_{mu p}(t*): stick within the bound (an elastic slip t / k), slip on it; r_q,t = w_t t.
///   An open point carries nothing and forgets its traction.
/// Neither is symmetric (the tangential force follows the pressure, not the reverse).
#include <memory>

#include "engine/contact/contact_definition.hpp"
#include "engine/contact/contact_law.hpp"
#include "engine/contact/point_law.hpp"

namespace lunaster::engine::contact {

/// Coulomb friction on `normal` (which must outlive it). `nodal_forces`: the normal law's force
/// is a spring force per node (discrete E_N), the tangential coefficient a stiffness per node.
/// PointKinematics: z = (LAGS_C if `normal` has it, then the tangential multipliers), mu and
/// coefficient_t the zone's; the state's history holds the penalty's traction.
std::unique_ptr<PointLaw> make_coulomb_law(const ContactLaw& normal, FrictionEnforcement how, bool nodal_forces);

}  // namespace lunaster::engine::contact
