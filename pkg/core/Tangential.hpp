// Sliding, rolling and torsion resistance of Luding 2008 (docs/tangential.md): one spring-dashpot-
// Coulomb element used three times, plus the contact kinematics. Header-only; Eigen, no YADE.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include "MesoParams.hpp"
#include <algorithm>
#include <cmath>

namespace meso {

using Vec3 = Eigen::Vector3d;

// Cross product written out: Eigen's cross() is not always inlined, and then binds to another
// library's instantiation through the PLT (measured: ~20 instructions per call in Law2::go()).
MESO_HOT Vec3 cross(const Vec3& a, const Vec3& b) { return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]); }

// Outcome of one step of an element: the (quasi-)force and whether it slipped.
template <class V> struct ElementStep {
	V    force;
	bool slipped = false;
};

// Dot product written out in Eigen's summation order a0 b0 + (a1 b1 + a2 b2) (same results), for the
// same reason: Eigen's dot() stays out of line in go().
MESO_HOT double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + (a[1] * b[1] + a[2] * b[2]); }
MESO_HOT double dot(double a, double b) { return a * b; } // the 1D element (torsion)

// a x + b y, written out for the same reason (Eigen's assignment kernels stay out of line in go()).
MESO_HOT Vec3   combine(double a, const Vec3& x, double b, const Vec3& y) { return Vec3(a * x[0] + b * y[0], a * x[1] + b * y[1], a * x[2] + b * y[2]); }
MESO_HOT double combine(double a, double x, double b, double y) { return a * x + b * y; }

MESO_HOT double magnitude(const Vec3& v) { return std::sqrt(dot(v, v)); }
MESO_HOT double magnitude(double v) { return std::abs(v); }
MESO_HOT double squared(const Vec3& v) { return dot(v, v); }
MESO_HOT double squared(double v) { return v * v; }

// One step of the spring-dashpot-Coulomb element (docs/tangential.md), V = Vec3 or double.
// The spring is advanced by v dt first (so the force belongs to this step's configuration, as
// the normal law does), then the trial force -k xi - gamma v is compared with the Coulomb limit;
// beyond it the force is the dynamic limit muD * level along the trial direction and the spring
// is reset to -(f + gamma v)/k so that sticking resumes without a jump.
// level = f_n + kc delta >= 0: the normal contact force measured from the adhesive branch.
// sliding: whether the element slipped at the previous step. A sticking element starts to slide
// beyond the static limit muS level; a sliding one goes on sliding while the trial exceeds the
// dynamic limit muD level (otherwise, with muD < muS, the reset spring would re-stick at once and
// the element would chatter between the limits instead of sliding at muD).
template <class V> MESO_HOT ElementStep<V> elementStep(const ElementParams& p, V& xi, const V& v, double dt, double level, bool& sliding)
{
	ElementStep<V> out;
	xi                 = combine(1.0, xi, dt, v);
	const V      trial = combine(-p.k, xi, -p.gamma, v);
	const double limit = (sliding ? p.muD : p.muS) * level;
	if (squared(trial) <= limit * limit) { // no square root while sticking
		sliding   = false;
		out.force = trial;
		return out;
	}
	sliding     = true;
	out.slipped = true;
	out.force   = trial * (p.muD * level / magnitude(trial));
	if (p.k > 0) xi = -(out.force + p.gamma * v) / p.k;
	else
		xi = xi * 0.0;
	return out;
}

// The rotation of the contact frame over one step: from the previous normal to the current one
// (the minimal rotation, exact) and about the normal by the mean spin of the pair. Computed once
// per step and applied to every vector of the tangent plane. For xi perpendicular to nPrev the
// minimal rotation reduces to xi - (xi.n)/(1 + c) (nPrev + n), c = nPrev.n, which is exactly
// perpendicular to n. The spin uses the Cayley form (cos, sin) = ((1 - t^2), 2t)/(1 + t^2),
// t = angle/2: exactly orthogonal, no trigonometric call, rotating by 2 atan(angle/2) =
// angle - angle^3/12 + ...
struct ContactRotation {
	Vec3     n, w; // current normal; (nPrev + n)/(1 + c)
	double   cosSpin = 1, sinSpin = 0;
	bool     tilt = false, spin = false;
	MESO_HOT ContactRotation(const Vec3& nPrev, const Vec3& nNow, double spinAngle)
	        : n(nNow)
	{
		// The per-step angles are tiny: 1/(1 + c) and 1/(1 + t^2) then come from series that are
		// exact to rounding (truncation below 1e-18 relative where used), sparing two
		// divisions on go()'s dependency chain; larger angles divide.
		const double c = dot(nPrev, nNow), u = 1 - c;
		tilt = c > -0.5; // a flip by more than 120 degrees in one step: no meaningful transport
		if (tilt) w = (nPrev + nNow) * (u < 1e-6 ? 0.5 * (1 + 0.5 * u * (1 + 0.5 * u)) : 1 / (1 + c));
		spin = spinAngle != 0;
		if (spin) {
			const double t = 0.5 * spinAngle, t2 = t * t;
			const double d = t2 < 1e-6 ? 1 - t2 * (1 - t2) : 1 / (1 + t2);
			cosSpin        = (1 - t2) * d;
			sinSpin        = 2 * t * d;
		}
	}
	// Transports xi (in the previous tangent plane) with the frame. A rigid rotation of the pair
	// thus leaves a spring unchanged in the pair's frame.
	MESO_HOT void apply(Vec3& xi) const
	{
		xi = tilt ? combine(1.0, xi, -dot(xi, n), w) : combine(1.0, xi, -dot(n, xi), n);
		if (spin) xi = combine(cosSpin, xi, sinSpin, cross(n, xi));
	}
};

MESO_INLINE void rotateWithContact(Vec3& xi, const Vec3& nPrev, const Vec3& n, double spinAngle) { ContactRotation(nPrev, n, spinAngle).apply(xi); }

// Arms from the centres to the contact point (a - delta/2 for a sphere, 0 for a wall, box or
// facet) and the lever arm a'_12 of rolling and torsion (docs/tangential.md).
struct ContactArms {
	double arm1 = 0, arm2 = 0, lever = 0;
};
MESO_HOT ContactArms contactArms(const PairParams& p, const PairGeometry& g, double delta)
{
	ContactArms c;
	c.arm1  = g.radius1 > 0 ? g.radius1 - 0.5 * delta : 0;
	c.arm2  = g.radius2 > 0 ? g.radius2 - 0.5 * delta : 0;
	c.lever = p.leverFactor * (g.radius1 > 0 && g.radius2 > 0 ? c.arm1 * c.arm2 / (c.arm1 + c.arm2) : std::max(c.arm1, c.arm2));
	return c;
}

// The stable step of a contact (the smallest over its normal limit branch kp with gamma0 and the
// sliding, rolling and torsion elements that act), at first touch (delta = 0). invMass1/2: 1/m of
// each body, invInertia1/2: 1/(smallest principal moment) (0 for a body that does not move). Names
// the element that limits it in *which (normal, sliding, rolling, torsion).
MESO_INLINE double
stableStep(const PairParams& p, const PairGeometry& g, double invMass1, double invMass2, double invInertia1, double invInertia2, const char** which)
{
	double best   = stableStep(p.kp, p.gammaN, invMass1 + invMass2);
	*which        = "normal";
	auto consider = [&](double dt, const char* name) {
		if (dt < best) {
			best   = dt;
			*which = name;
		}
	};
	const ContactArms arms = contactArms(p, g, 0.0);
	if (p.slidingActs) // the contact point moves with both spheres' spins too
		consider(
		        stableStep(
		                p.sliding.k, p.sliding.gamma, invMass1 + invMass2 + arms.arm1 * arms.arm1 * invInertia1 + arms.arm2 * arms.arm2 * invInertia2),
		        "sliding");
	const double invRot = arms.lever * arms.lever * (invInertia1 + invInertia2); // v_r = a' (w1 - w2), torque a' f on each
	if (p.rollingActs) consider(stableStep(p.rolling.k, p.rolling.gamma, invRot), "rolling");
	if (p.torsionActs) consider(stableStep(p.torsion.k, p.torsion.gamma, invRot), "torsion");
	return best;
}

// Relative velocities at a contact of body 1 with body 2; n points from 1 to 2 (YADE's normal).
struct ContactVelocities {
	Vec3   sliding; // v_t: tangential velocity of 1 relative to 2 at the contact point [m/s]
	Vec3   rolling; // v_r = a'_ij n x (w1 - w2) [m/s]
	double torsion; // v_o = a'_ij n.(w1 - w2) [m/s], along n
};

// Velocity of the contact point of sphere 1 relative to sphere 2: the branches are +-arm n
// (arm = a - delta/2), so v1 - v2 + arm1 w1 x n + arm2 w2 x n takes one cross product.
MESO_HOT Vec3 sphereContactVelocity(const Vec3& n, const Vec3& relVel, const Vec3& w1, const Vec3& w2, double arm1, double arm2)
{
	return relVel + cross(arm1 * w1 + arm2 * w2, n);
}

// Sliding, rolling and torsion velocities from the contact-point velocity vc, the relative
// angular velocity dw = w1 - w2 and the lever arm a'_ij.
MESO_HOT ContactVelocities contactVelocities(const Vec3& n, const Vec3& vc, const Vec3& dw, double leverArm)
{
	ContactVelocities c;
	c.sliding = combine(1.0, vc, -dot(n, vc), n);
	c.rolling = leverArm * cross(n, dw);
	c.torsion = leverArm * dot(n, dw);
	return c;
}

// Energy absorbed by an element over one step (trapezoid of the force over the relative
// displacement v dt, with the previous step's force), and its stored spring energy [J].
template <class V> MESO_INLINE double absorbedWork(const V& prevForce, const V& force, const V& v, double dt)
{
	return -0.5 * dt * (dot(prevForce, v) + dot(force, v));
}
MESO_INLINE double springEnergy(const ElementParams& p, const Vec3& xi) { return 0.5 * p.k * xi.squaredNorm(); }
MESO_INLINE double springEnergy(const ElementParams& p, double xi) { return 0.5 * p.k * xi * xi; }

// What a contact remembers of its tangential mechanisms; forces are those of the last step,
// acting on body 1 (body 2 gets the opposite). The sliding force is not here: YADE keeps it as
// the IPhys's shearForce, and a copy would only cost memory.
struct TangentialState {
	Vec3   xiT      = Vec3::Zero();                              // sliding spring [m]
	Vec3   xiR      = Vec3::Zero();                              // rolling spring [m]
	double xiO      = 0;                                         // torsion spring, along n [m]
	Vec3   fR       = Vec3::Zero();                              // rolling quasi-force [N]
	double fO       = 0;                                         // torsion quasi-force, along n [N]
	Vec3   nPrev    = Vec3::Zero();                              // normal of the previous step (zero: none yet)
	bool   slidingT = false, slidingR = false, slidingO = false; // elements slipping at the last step
	void   reset() { *this = TangentialState(); }
};

// Energy of one step: stored spring energy (half-step consistent with YADE's leapfrog kinetic
// energy, reset every step) and the increments of dissipation of each mechanism [J].
struct TangentialEnergy {
	double stored = 0, sliding = 0, rolling = 0, torsion = 0;
};

// One step of all tangential mechanisms of a contact in mechanical contact (those that act: the
// flags of p). level: f_n + kc delta (clamped at 0 here). energy may be null; inlined, so that a
// caller passing nullptr gets no bookkeeping code at all.
// fT: the sliding force on body 1, the last step's on entry, this step's on return.
MESO_INLINE void tangentialStep(
        const PairParams&        p,
        TangentialState&         s,
        Vec3&                    fT,
        const ContactVelocities& v,
        const Vec3&              n,
        double                   spinAngle,
        double                   dt,
        double                   level,
        TangentialEnergy*        energy)
{
	if (level < 0) level = 0;
	if (dot(s.nPrev, s.nPrev) > 0) {
		const ContactRotation rot(s.nPrev, n, spinAngle);
		if (p.slidingActs) rot.apply(s.xiT);
		if (p.rollingActs) rot.apply(s.xiR);
		if (energy) { // the previous forces serve only the energy bookkeeping
			rot.apply(fT);
			rot.apply(s.fR);
		}
	}
	s.nPrev            = n;
	const Vec3   prevT = fT, prevR = s.fR;
	const double prevO = s.fO;
	double       uT0 = 0, uR0 = 0, uO0 = 0;
	if (energy) {
		uT0 = springEnergy(p.sliding, s.xiT);
		uR0 = springEnergy(p.rolling, s.xiR);
		uO0 = springEnergy(p.torsion, s.xiO);
	}
	if (p.slidingActs) fT = elementStep(p.sliding, s.xiT, v.sliding, dt, level, s.slidingT).force;
	if (p.rollingActs) s.fR = elementStep(p.rolling, s.xiR, v.rolling, dt, level, s.slidingR).force;
	if (p.torsionActs) s.fO = elementStep(p.torsion, s.xiO, v.torsion, dt, level, s.slidingO).force;
	if (!energy) return;
	const double uT = springEnergy(p.sliding, s.xiT), uR = springEnergy(p.rolling, s.xiR), uO = springEnergy(p.torsion, s.xiO);
	energy->sliding = absorbedWork(prevT, fT, v.sliding, dt) - (uT - uT0);
	energy->rolling = absorbedWork(prevR, s.fR, v.rolling, dt) - (uR - uR0);
	energy->torsion = absorbedWork(prevO, s.fO, v.torsion, dt) - (uO - uO0);
	energy->stored  = uT + uR + uO + 0.5 * dt * (fT.dot(v.sliding) + s.fR.dot(v.rolling) + s.fO * v.torsion);
}

// The step at which the contact ends (delta <= 0): forces vanish; what the springs held is lost.
MESO_INLINE void tangentialRelease(const PairParams& p, TangentialState& s, Vec3& fT, const ContactVelocities& v, double dt, TangentialEnergy* energy)
{
	if (energy) {
		energy->sliding = absorbedWork(fT, Vec3(Vec3::Zero()), v.sliding, dt) + springEnergy(p.sliding, s.xiT);
		energy->rolling = absorbedWork(s.fR, Vec3(Vec3::Zero()), v.rolling, dt) + springEnergy(p.rolling, s.xiR);
		energy->torsion = absorbedWork(s.fO, 0.0, v.torsion, dt) + springEnergy(p.torsion, s.xiO);
		energy->stored  = 0;
	}
	s.reset();
	fT = Vec3::Zero();
}

} // namespace meso
