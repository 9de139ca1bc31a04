#include "MesoParams.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace meso {

namespace {
	[[noreturn]] void reject(const char* name, double value, const char* rule)
	{
		std::ostringstream msg;
		msg.precision(17);
		msg << name << " = " << value << " is invalid: " << rule;
		throw std::invalid_argument(msg.str());
	}
	void finite(const char* name, double v)
	{
		if (!std::isfinite(v)) reject(name, v, "must be a finite number");
	}
}

Adhesion parseAdhesion(const std::string& s)
{
	if (s == "none") return Adhesion::None;
	if (s == "reversible") return Adhesion::Reversible;
	if (s == "jumpIn") return Adhesion::JumpIn;
	throw std::invalid_argument("adhesion = '" + s + "' is invalid: must be 'none', 'reversible' or 'jumpIn'");
}

K2Interpolation parseK2Interpolation(const std::string& s)
{
	if (s == "linear") return K2Interpolation::Linear;
	if (s == "sqrt") return K2Interpolation::Sqrt;
	throw std::invalid_argument("k2Interpolation = '" + s + "' is invalid: must be 'linear' or 'sqrt'");
}

const char* adhesionName(Adhesion a)
{
	switch (a) {
		case Adhesion::Reversible: return "reversible";
		case Adhesion::JumpIn: return "jumpIn";
		default: return "none";
	}
}

const char* k2InterpolationName(K2Interpolation k) { return k == K2Interpolation::Sqrt ? "sqrt" : "linear"; }

void validate(const MaterialParams& m)
{
	finite("k1", m.k1);
	finite("kp", m.kp);
	finite("kc", m.kc);
	finite("phiF", m.phiF);
	finite("fa", m.fa);
	finite("kca", m.kca);
	finite("gammaN", m.gammaN);
	if (!(m.k1 > 0)) reject("k1", m.k1, "the loading stiffness must be > 0");
	if (!(m.kp >= m.k1)) reject("kp", m.kp, "the limit stiffness must be >= k1");
	if (!(m.kc >= 0)) reject("kc", m.kc, "the adhesive stiffness must be >= 0");
	if (!(m.phiF > 0 && m.phiF <= 1)) reject("phiF", m.phiF, "the plasticity depth must lie in (0, 1]");
	if (!(m.fa >= 0)) reject("fa", m.fa, "the non-contact adhesive force must be >= 0");
	if (!(m.kca >= 0)) reject("kca", m.kca, "the non-contact adhesive stiffness must be >= 0");
	if (m.fa > 0 && !(m.kca > 0)) reject("kca", m.kca, "must be > 0 when fa > 0 (the range of the non-contact force is fa/kca)");
	if (m.fa > 0 && !std::isfinite(m.fa / m.kca)) reject("kca", m.kca, "too small for fa: the range fa/kca of the non-contact force must be finite");
	if (m.fa > 0 && m.adhesion == Adhesion::None)
		throw std::invalid_argument("adhesion = 'none' is invalid with fa > 0: choose 'reversible' or 'jumpIn', or set fa = 0");
	if (!(m.gammaN >= 0)) reject("gammaN", m.gammaN, "the viscous damping must be >= 0");
	const struct {
		const char* name;
		double      value;
	} nonNegative[] = { { "muS", m.muS }, { "kt", m.kt }, { "gammaT", m.gammaT }, { "kr", m.kr },
		            { "gammaR", m.gammaR },                  { "muR", m.muR }, { "ko", m.ko },         { "gammaO", m.gammaO },
		            { "muO", m.muO } };
	for (const auto& q : nonNegative) {
		finite(q.name, q.value);
		if (!(q.value >= 0)) reject(q.name, q.value, "must be >= 0");
	}
	finite("phiD", m.phiD);
	if (!(m.phiD > 0 && m.phiD <= 1)) reject("phiD", m.phiD, "the dynamic/static friction ratio must lie in (0, 1]");
}

double harmonicMean(double x, double y)
{
	if (x == 0 || y == 0) return 0.0;
	// Scaled by the larger value: 2xy/(x+y) itself overflows for finite x, y above ~1e154.
	const double s = std::max(x, y), u = x / s, v = y / s;
	return s * (2 * (u * v / (u + v))); // <= s: 2 s itself can overflow
}

void setMechanisms(PairParams& p, bool geometryWithRotations)
{
	p.tangential = p.sliding.active() || p.rolling.active() || p.twisting.active();
	p.rollTwist  = (p.rolling.active() || p.twisting.active()) && geometryWithRotations;
	p.slides     = p.sliding.active();
	p.rolls      = p.rollTwist && p.rolling.active();
	p.twists     = p.rollTwist && p.twisting.active();
}

PairGeometry pairGeometry(const PairParams& p, double radius1, double radius2)
{
	PairGeometry g;
	g.radius1 = radius1;
	g.radius2 = radius2;
	// 0 when purely elastic (kp == k1): the limit branch is never reached.
	g.invDeltaMaxP = p.kp > p.k1 ? (p.kp - p.k1) / (p.kp * p.phiF * g.a12()) : 0.0;
	return g;
}

double stableStep(double k, double gamma, double invMass)
{
	if (!(invMass > 0)) return std::numeric_limits<double>::infinity();
	if (k <= 0) return gamma > 0 ? 2 / (gamma * invMass) : std::numeric_limits<double>::infinity();
	const double m = 1 / invMass, w = std::sqrt(k * invMass), z = gamma / (2 * std::sqrt(k * m));
	return 2 / w / (std::sqrt(1 + z * z) + z); // = (2/w)(sqrt(1+z^2) - z), without the cancellation
}

PairParams mixPair(const MaterialParams& mat1, const MaterialParams& mat2)
{
	const bool            one = mat1.dominant && !mat2.dominant, two = mat2.dominant && !mat1.dominant;
	const MaterialParams& m1  = two ? mat2 : mat1;
	const MaterialParams& m2  = one ? mat1 : mat2;
	PairParams            p;
	p.k1     = harmonicMean(m1.k1, m2.k1);
	p.kp     = std::max(harmonicMean(m1.kp, m2.kp), p.k1); // monotone mean keeps kp >= k1; max() guards rounding
	p.kc     = harmonicMean(m1.kc, m2.kc);
	p.phiF   = 0.5 * (m1.phiF + m2.phiF);
	p.fa     = harmonicMean(m1.fa, m2.fa);
	p.kca    = harmonicMean(m1.kca, m2.kca);
	p.gammaN = harmonicMean(m1.gammaN, m2.gammaN);
	auto strength = [](Adhesion a) { return a == Adhesion::None ? 0 : (a == Adhesion::JumpIn ? 1 : 2); };
	p.adhesion    = strength(m1.adhesion) <= strength(m2.adhesion) ? m1.adhesion : m2.adhesion;
	p.k2Interpolation = (m1.k2Interpolation == K2Interpolation::Sqrt && m2.k2Interpolation == K2Interpolation::Sqrt)
	        ? K2Interpolation::Sqrt
	        : K2Interpolation::Linear;
	if (p.adhesion == Adhesion::None) p.fa = 0;
	const double phiD = std::min(m1.phiD, m2.phiD);
	auto element = [phiD](double k1_, double k2_, double g1, double g2, double mu1, double mu2) {
		ElementParams e;
		e.k     = harmonicMean(k1_, k2_);
		e.gamma = harmonicMean(g1, g2);
		e.muS   = std::min(mu1, mu2);
		e.muD   = phiD * e.muS;
		return e;
	};
	p.sliding  = element(m1.kt, m2.kt, m1.gammaT, m2.gammaT, m1.muS, m2.muS);
	p.rolling  = element(m1.kr, m2.kr, m1.gammaR, m2.gammaR, m1.muR, m2.muR);
	p.twisting = element(m1.ko, m2.ko, m1.gammaO, m2.gammaO, m1.muO, m2.muO);
	p.deltaA        = (p.fa > 0 && p.adhesion != Adhesion::None) ? -p.fa / p.kca : 0.0;
	p.delta0PerMaxP = p.kp > p.k1 ? 1 - p.k1 / p.kp : 0.0;
	return p;
}

} // namespace meso
