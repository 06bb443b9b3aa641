#pragma once
// Everything the contact evaluation adds to the seed's Algorithms 2 and 3
// (constraint_evaluation.h), and the rest gap the contact rows add, in one
// place: each field is a runtime setting
// with its unit and the reason it exists, and
// docs/decisions/008-contact-evaluation-rules.md gives the measurements
// behind each value. Velocity steps are in epsilon_2 (the solver's
// constraint_tolerance, m/s), angles in rad; shares and cosines are plain
// numbers.
// Two rules have no number: sticking/sliding changes and Algorithm 3 wait
// for a converged evaluation (a half-converged iterate cycled), and a
// contact past max_flips (ContactSolverSettings) is frozen active.

namespace recoil::sim {

// The longest moving-average window ContactTrack can hold.
inline constexpr int kMaxLambdaWindow = 8;

struct ContactPolicy {
  // Share of the collision margin at which approaching contacts come to
  // rest (sim/contact/contact_model.h): at zero distance the next step
  // cannot tell a vertex on a corner from one beside it, and a stack of
  // boxes fell through itself.
  double rest_gap_fraction = 0.1;
  // Evaluations averaged into lambda' (Algorithm 3's simple moving average;
  // the seed leaves its length open): short enough to reach lambda three
  // evaluations after it settles, long enough to damp coupled contacts.
  int lambda_window = 3;
  // Gain of a slip-direction turn, the seed's alpha_theta: 1 aims straight at
  // the fixed point of an isolated contact.
  double alpha_theta = 1.0;
  // rad: a direction change below this is round-off, not a turn (the seed's
  // epsilon_theta).
  double eps_theta = 1e-10;
  // Turns the same way after which a halved gain doubles back (a turn against
  // the last one halves it): coupled contacts swing period-2 at full gain.
  int alpha_streak = 4;
  // -cosine past which a sliding contact's slip counts as reversed and it
  // sticks (0.5: 120 degrees); a slip turned less is a direction to follow.
  double reversal = 0.5;
  // Share of the largest violation (m/s) within which proposed mode changes
  // are applied; the rest wait: all at once over-constrains a landing corner
  // and cycles.
  double change_share = 0.9;
  // Cosine (in the P_A^-1 metric) above which two normal rows count as one:
  // an activation that parallel to a row already on waits, so near-duplicate
  // rows never come on together.
  double parallel = 0.9;
  // In epsilon_2: the smallest friction step taken while the friction law is
  // off by more than epsilon_2, so a decayed gain cannot hide a wrong slip;
  // just above what Algorithm 2 accepts, since a longer step overshoots a
  // fixed point that coupled contacts share and swings across it.
  double registered_change = 1.05;
  // A secant turn of the slip only where the direction error contracts by
  // less than this per solve (linear convergence beside sticking neighbours)...
  double secant_contraction = 0.95;
  // ... is at most this many times the error (an unbounded secant diverged)...
  double secant_reach = 8.0;
  // ... and only for errors below this, rad.
  double secant_range = 0.1;
};

}  // namespace recoil::sim
