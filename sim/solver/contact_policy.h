#pragma once
// Everything the contact evaluation adds to the seed's Algorithms 2 and 3
// (constraint_evaluation.h), and the rest gap the contact rows add, in one
// place: each field is a runtime setting with its unit and the reason it
// exists, and docs/decisions/008-contact-evaluation-rules.md gives the
// measurements behind each value. Shares and cosines are plain numbers.
// Three rules have no tuned number: sticking/sliding changes and Algorithm 3 wait
// for a converged evaluation (a half-converged iterate cycled); static
// friction acts on contacts whose sides are at relative rest (one that comes
// on at rest has no slip direction and sticks at the converged evaluation;
// one that breaks away keeps mu_static until its slip starts:
// ContactState::impending; one still sliding when a step begins with its
// sides at rest starts the step sticking); and a row that depends exactly
// on the rows that are on (normal rows, and sticking contacts' tangent rows)
// comes on only where their right-hand sides agree: otherwise an activation
// comes on in exchange for one of them, which switches off or slides (a dual
// active-set ratio test), and a sliding contact about to stick keeps
// sliding (the dependence test's tolerance is rounding:
// docs/decisions/023-dependent-rows-exchange.md). Algorithm 3's
// extrapolation keeps its own depth (FrictionAcceleration::kDepth).

namespace recoil::sim {

struct ContactPolicy {
  // Share of the collision margin at which approaching contacts come to
  // rest (sim/contact/contact_model.h): at zero distance the next step
  // cannot tell a vertex on a corner from one beside it, and a stack of
  // boxes fell through itself.
  double rest_gap_fraction = 0.1;
  // Share of Algorithm 3's step, G(x) - x, that one evaluation takes
  // (friction_acceleration.h): the whole step swings coupled contacts
  // period-2 (the bunny-drop demo: 21 capped steps against 3 at a half).
  double friction_mixing = 0.5;
  // -cosine past which a sliding contact's slip counts as reversed and it
  // sticks (0.5: 120 degrees); a slip turned less is a direction to follow.
  double reversal = 0.5;
  // Cosine (in the P_A^-1 metric) above which two normal rows count as one:
  // an activation that parallel to a row already on waits, so near-duplicate
  // rows never come on together.
  double parallel = 0.9;
};

}  // namespace recoil::sim
