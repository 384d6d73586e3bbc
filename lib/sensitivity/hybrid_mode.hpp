#pragma once
// Vocabulary of the sensitivity module: the discrete mode of a hybrid trajectory (one phase per
// contact), the guards that end a mode (source B.3.3), and a micro event (one guard crossing
// with its mode change, source C.2/D.1).
//
// Planar slip carries its direction s = ±1 (the sign of ζ_t while slipping), because the slip
// vector field λ_t = −μ λ_n s is smooth only with s fixed: inside one mode the variational flow
// differentiates it with s constant.
//
// Spatial slip (tangent dimension 2) is the phase kSlipPositive with a reference direction
// s_ref (unit, 2 entries): the friction is λ_t = −μ λ_n ε(ζ_t), ε(ζ_t) = ±ζ_t/‖ζ_t‖ oriented
// along s_ref, so the direction turns with ζ_t during the flow (and the variational flow
// differentiates that turn), while s_ref keeps the vector field smooth through ζ_t = 0 on a
// straight path and gives its one-sided limit there, as the event-driven engine's does.
#include <string>
#include <string_view>
#include <vector>

namespace impactbench::sensitivity {

/// Phase of one contact. A closed frictionless contact (μ = 0) is a slip phase (its friction
/// force is zero whatever s).
enum class ContactPhase { kOpen, kSlipPositive, kSlipNegative, kStick };

/// One phase per contact, in the order of LagrangianSystem::find_contacts, and the spatial slip
/// references (slip_reference[i] empty for planar systems and non-slipping contacts; the whole
/// list may be empty). Modes compare by their phases.
struct HybridMode : std::vector<ContactPhase> {
  using std::vector<ContactPhase>::vector;
  std::vector<std::vector<double>> slip_reference;
  /// s_ref of contact i (empty when none).
  const std::vector<double>& reference(int i) const;
};

/// The guard functions γ, positive inside the mode and crossing zero at the event:
enum class GuardKind {
  kImpact,       ///< open:  γ = h_n (the gap closes)
  kLiftOff,      ///< closed: γ = λ_n (B.38, depends on u)
  kSlipToStick,  ///< slip:  γ = s ζ_t (the slip velocity vanishes)
  kStickToSlip,  ///< stick: γ = μ λ_n + s λ_t for the new slip direction s (B.43 with μ)
};

/// One guard crossing: contact `contact` reaches guard `kind` and takes phase `phase_after`.
/// For an impact, `phase_after` is open (bounce, e > 0) or a closed phase (e = 0).
/// An impact's impulse acts on the other closed contacts too and may change their phase (a
/// sliding corner reversing or stopping when the opposite corner lands, the old pivot of a
/// rocking block lifting off). Those changes are not guard crossings; they belong to the
/// impact's reset (whose constraints are those of the mode after) and are listed in `carried`.
struct CarriedPhase {
  int contact = 0;
  ContactPhase phase_after = ContactPhase::kStick;
  friend bool operator==(const CarriedPhase&, const CarriedPhase&) = default;
};

struct MicroEvent {
  int contact = 0;
  GuardKind kind = GuardKind::kImpact;
  ContactPhase phase_after = ContactPhase::kOpen;
  std::vector<CarriedPhase> carried = {};  ///< impacts only
  /// A bouncing impact (phase_after open, e > 0, μ > 0): the tangential law of its impulse,
  /// kStick (ζ_t⁺ = 0, Γ ≥ 0) or a slip phase (Λ_t = −μ Λ_n s). kOpen: slip along ζ_t⁻ (B.21).
  ContactPhase bounce_impulse = ContactPhase::kOpen;
  /// Spatial slip after the event: the reference direction s_ref of the new slip phase.
  std::vector<double> slip_reference = {};
  friend bool operator==(const MicroEvent&, const MicroEvent&) = default;
};

bool is_closed(ContactPhase phase);
/// s of a slip phase (+1 / −1); 0 for open and stick.
int slip_direction(ContactPhase phase);
/// The mode after `event`: the event's contact, and for an impact its carried phases.
HybridMode apply_event(const HybridMode& mode, const MicroEvent& event);

std::string_view to_string(ContactPhase phase);
std::string_view to_string(GuardKind kind);
/// e.g. "1:impact->open".
std::string to_string(const MicroEvent& event);
/// e.g. "open|slip+".
std::string to_string(const HybridMode& mode);

}  // namespace impactbench::sensitivity
