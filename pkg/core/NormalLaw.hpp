// The normal force of the meso-particle law (docs/model.md §3–5): hysteretic contact force with the
// exact history update, non-contact adhesion, viscous damping, and the per-contact energy
// bookkeeping. Header-only so that it inlines into Law2::go(); no YADE here.
#pragma once
#include "MesoParams.hpp"
#include <cmath>
#include <limits>

namespace meso {

// What one contact remembers. deltaMax is the only true state of the hysteresis; delta0 is a
// cached function of it (it changes only when deltaMax does, and takes a division). k2 is not
// kept: unloadingStiffness() is cheaper than the memory a contact would carry for it.
struct NormalHistory {
	double deltaMax = 0;     // largest overlap of the current contact (after -kc resets) [m]
	double delta0   = 0;     // force-free overlap of the current k2 line [m]
	bool   touched  = false; // the pair has been in mechanical contact (jump-in adhesion)
};

// The three parts of the normal force (> 0 repulsive) [N].
struct NormalForce {
	double hysteretic = 0, adhesive = 0, viscous = 0;
	double total() const { return hysteretic + adhesive + viscous; }
};

// What the Coulomb limits of sliding, rolling and torsion scale with (Luding 2008): the contact part
// of the normal force, hysteretic plus viscous (not the non-contact -fa), measured from the adhesive
// branch -kc delta, so that a contact held at its tensile limit can still resist.
MESO_HOT double coulombLevel(const PairParams& p, double hysteretic, double viscous, double delta) { return hysteretic + viscous + p.kc * delta; }

// The un-/re-loading stiffness k2(deltaMax) (Eqs. 9, 10, D.1): k1 on a fresh contact, kp beyond deltaMaxP.
MESO_HOT double unloadingStiffness(const PairParams& p, const PairGeometry& g, double deltaMax)
{
	const double x = deltaMax * g.invDeltaMaxP;
	if (x >= 1) return p.kp;
	return p.k1 + (p.kp - p.k1) * (p.k2Interpolation == K2Interpolation::Sqrt ? std::sqrt(x) : x);
}
MESO_HOT double unloadingStiffness(const PairParams& p, const PairGeometry& g, const NormalHistory& h) { return unloadingStiffness(p, g, h.deltaMax); }

// Moves the history to the un-/re-loading line of deltaMax (delta0 from Eqs. 7, 11); returns its k2.
MESO_HOT double setUnloadingLine(const PairParams& p, const PairGeometry& g, NormalHistory& h, double deltaMax)
{
	h.deltaMax      = deltaMax;
	const double k2 = unloadingStiffness(p, g, deltaMax);
	// On the limit branch phiF a12 (Eq. 11), continuous with the k2 lines at deltaMaxP.
	h.delta0 = deltaMax * g.invDeltaMaxP >= 1 ? p.delta0PerMaxP * g.deltaMaxP() : (1 - p.k1 / k2) * deltaMax;
	return k2;
}

// The deltaMax whose k2 line passes through (delta, -kc delta) on the tensile branch: the root of
// (k2(dm) - k1) dm = (k2(dm) + kc) delta, solved in closed form (no lagged k2).
MESO_INLINE double deltaMaxThrough(const PairParams& p, const PairGeometry& g, double delta)
{
	const double x = delta * g.invDeltaMaxP;
	const double q = (p.k1 + p.kc) / (p.kp - p.k1); // (1 + beta)/eta
	if (p.k2Interpolation == K2Interpolation::Linear) {
		// c dm^2 - c delta dm - (k1 + kc) delta = 0 with c = (kp - k1)/deltaMaxP, in units of deltaMaxP
		return g.deltaMaxP() * (0.5 * x + std::sqrt(0.25 * x * x + q * x));
	}
	// k2 = k1 (1 + eta s), dm = deltaMaxP s^2:  s^3 - x s - q x = 0, one positive root
	const double P = -x, Q = -q * x;
	const double D = 0.25 * Q * Q + P * P * P / 27;
	double       s;
	if (D >= 0) {
		const double r = std::sqrt(D);
		s              = std::cbrt(-0.5 * Q + r) + std::cbrt(-0.5 * Q - r);
	} else {
		s = 2 * std::sqrt(-P / 3) * std::cos(std::acos(1.5 * Q / P * std::sqrt(-3 / P)) / 3);
	}
	s -= (s * s * s + P * s + Q) / (3 * s * s + P); // one Newton step polishes rounding
	return g.deltaMaxP() * s * s;
}

// Hysteretic contact force at overlap delta; updates the history first (docs/model.md §3 order).
MESO_HOT double hystereticForce(const PairParams& p, const PairGeometry& g, NormalHistory& h, double delta)
{
	if (delta <= 0) { // mechanical contact over: the next one starts new
		h.deltaMax = 0;
		h.delta0   = 0;
		return 0;
	}
	// Beyond deltaMax the k2 line of delta meets k1 delta (or the kp branch) here.
	const double k2   = delta > h.deltaMax ? setUnloadingLine(p, g, h, delta) : unloadingStiffness(p, g, h);
	const double f    = k2 * (delta - h.delta0);
	const double fMin = -p.kc * delta;
	if (f >= fMin) return f;
	setUnloadingLine(p, g, h, deltaMaxThrough(p, g, delta)); // moving along -kc changes the history
	return fMin;
}

// Non-contact adhesion superposed on the contact force (Eqs. 14, 15 and the jump-in tail).
MESO_HOT double adhesiveForce(const PairParams& p, NormalHistory& h, double delta)
{
	if (p.adhesion == Adhesion::None) return 0;
	if (!actsAcrossGap(p.adhesion) && !h.touched) {
		if (delta <= 0) return 0;
		h.touched = true;
	}
	if (delta > 0) return -p.fa;
	if (delta > p.deltaA) return -p.kca * delta - p.fa;
	return 0;
}

// The adhesive force that adhesiveForce() gave at delta, from the history it left (a copy: nothing
// changes). A contact keeps no copy of that force: it is a function of delta and the jump-in flag.
MESO_INLINE double adhesiveForceAfter(const PairParams& p, NormalHistory h, double delta) { return adhesiveForce(p, h, delta); }

// All parts of the normal force; vn = d(delta)/dt, > 0 while approaching [m/s].
MESO_HOT NormalForce normalForce(const PairParams& p, const PairGeometry& g, NormalHistory& h, double delta, double vn)
{
	NormalForce f;
	f.hysteretic = hystereticForce(p, g, h, delta);
	f.adhesive   = adhesiveForce(p, h, delta);
	f.viscous    = delta > 0 ? (p.gammaN + p.gammaN2 * std::abs(vn)) * vn : 0.0; // gammaN2 = 0: gammaN vn exactly
	return f;
}

// Whether the pair still interacts: while the non-contact force can act (delta > deltaA), or in contact.
MESO_HOT bool keepsInteracting(const PairParams& p, double delta) { return delta > p.deltaA; }

// Elastic energy stored on the current un-/re-loading line: 1/2 k2 (delta - delta0)^2 = f^2/(2 k2) [J].
MESO_INLINE double storedElastic(const PairParams& p, const PairGeometry& g, const NormalHistory& h, double fHysteretic)
{
	const double k2 = unloadingStiffness(p, g, h);
	return k2 > 0 ? 0.5 * fHysteretic * fHysteretic / k2 : 0.0;
}

// Energy bookkeeping of one contact consistent with YADE's leapfrog integrator, whose kinetic
// energy at step n uses the velocity of step n-1/2: the work absorbed by the contact up to that
// time is the trapezoidal sum up to step n minus f_n (delta_n - delta_{n-1})/2.
struct NormalEnergyStep {
	double elastic  = 0; // stored elastic energy, half-step consistent (reset every step) [J]
	double plastic  = 0; // increment of hysteretic dissipation [J]
	double adhesive = 0; // increment of the work absorbed by the adhesive force (< 0 while binding) [J]
	double viscous  = 0; // increment of viscous dissipation [J]
};

// prev, prevDelta, prevElastic: the force parts, overlap and storedElastic() of the previous step
// (zero force before the first one); f, delta: this step's, h after this step's update. The previous
// stored energy is not kept: it is storedElastic() of the previous force and history, which the
// caller evaluates before the update.
MESO_INLINE NormalEnergyStep energyStep(
        const PairParams&    p,
        const PairGeometry&  g,
        double               prevDelta,
        double               prevElastic,
        const NormalHistory& h,
        const NormalForce&   prev,
        const NormalForce&   f,
        double               delta)
{
	const double     dd      = delta - prevDelta;
	const double     elastic = storedElastic(p, g, h, f.hysteretic);
	NormalEnergyStep e;
	e.plastic  = 0.5 * (prev.hysteretic + f.hysteretic) * dd - (elastic - prevElastic);
	e.adhesive = 0.5 * (prev.adhesive + f.adhesive) * dd;
	e.viscous  = 0.5 * (prev.viscous + f.viscous) * dd;
	e.elastic  = elastic - 0.5 * f.total() * dd;
	return e;
}

// What a contact keeps of its last step: enough to rebuild that step's force parts and stored
// energy (the adhesive part and the energy are functions of the overlap and the history).
struct NormalMemory {
	double fHysteretic = 0, fViscous = 0;
	double lastDelta = std::numeric_limits<double>::quiet_NaN(); // NaN before the law's first step
};

// One step of the normal law with its energy: the previous step rebuilt from last (before the
// history changes), this step's force (h updated; the caller keeps it as the next step's last),
// and the increments of energyStep(). On
// the law's first step the contact is taken as having been at delta - vn dt already: zero for a pair
// coming from outside the force's range; spheres that start overlapped hold their initial elastic
// energy (in e.elastic), not work done in this step (which would read as negative dissipation).
MESO_INLINE NormalForce normalStepWithEnergy(
        const PairParams& p, const PairGeometry& g, NormalHistory& h, const NormalMemory& last, double delta, double vn, double dt, NormalEnergyStep& e)
{
	const bool   first     = std::isnan(last.lastDelta);
	const double prevDelta = first ? delta - vn * dt : last.lastDelta;
	NormalForce  prev;
	double       prevElastic;
	if (!first) {
		prev.hysteretic = last.fHysteretic;
		prev.adhesive   = adhesiveForceAfter(p, h, prevDelta);
		prev.viscous    = last.fViscous;
		prevElastic     = storedElastic(p, g, h, prev.hysteretic);
	} else {
		NormalHistory fresh;
		prev        = normalForce(p, g, fresh, prevDelta, vn);
		prevElastic = storedElastic(p, g, fresh, prev.hysteretic);
	}
	const NormalForce f = normalForce(p, g, h, delta, vn);
	e                   = energyStep(p, g, prevDelta, prevElastic, h, prev, f, delta);
	return f;
}

// Which branch of the law a contact was on at its last step, read back from what the step left
// (the overlap, the history after the update, the hysteretic force): nothing is stored for it, so
// the hot path pays nothing. Loading sets deltaMax to the overlap itself; the tensile limit returns
// -kc delta itself; both are exact equalities of what the step computed.
#define MESO_BRANCHES(X)                                                                                                                                       \
	X(New, "new") X(Apart, "apart") X(NonContact, "nonContact") X(Loading, "loading") X(Limit, "limit") X(Unloading, "unloading") X(Tensile, "tensile")
#define MESO_BRANCH_ENUM(e, name) e,
enum class Branch : int { MESO_BRANCHES(MESO_BRANCH_ENUM) };
#undef MESO_BRANCH_ENUM
#define MESO_BRANCH_NAME(e, name) name,
constexpr const char* kBranchNames[] = { MESO_BRANCHES(MESO_BRANCH_NAME) };
#undef MESO_BRANCH_NAME
constexpr int      kBranchCount = sizeof(kBranchNames) / sizeof(kBranchNames[0]);
inline const char* branchName(Branch b) { return kBranchNames[static_cast<int>(b)]; }
MESO_INLINE Branch branchAfter(const PairParams& p, const PairGeometry& g, const NormalHistory& h, double delta, double fHysteretic)
{
	if (std::isnan(delta)) return Branch::New; // no step yet
	if (delta <= 0) return adhesiveForceAfter(p, h, delta) != 0 ? Branch::NonContact : Branch::Apart;
	if (fHysteretic == -p.kc * delta) return Branch::Tensile;
	if (delta == h.deltaMax) return delta * g.invDeltaMaxP >= 1 ? Branch::Limit : Branch::Loading;
	return Branch::Unloading;
}

} // namespace meso
