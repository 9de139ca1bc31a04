#include "MesoParams.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>

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
		// Beyond these the law's own products (k delta^2, f^2/k, 1/m, the stable step) leave floating
		// point while the value itself is still finite: garbage without a word.
		if (v != 0 && !(std::abs(v) >= kSmallestValue && std::abs(v) <= kLargestValue))
			reject(name, v, "lies outside [1e-100, 1e100] (0 allowed): the law's products of it would overflow or underflow");
	}
}

std::string adhesionChoices()
{
	std::string out;
	for (int k = 0; k < kAdhesionModeCount; ++k)
		out += (k == 0 ? "'" : (k + 1 == kAdhesionModeCount ? " or '" : ", '")) + std::string(kAdhesionModes[k].name) + "'";
	return out;
}

Adhesion parseAdhesion(const std::string& s)
{
	for (const AdhesionMode& m : kAdhesionModes)
		if (s == m.name) return m.mode;
	throw std::invalid_argument("adhesion = '" + s + "' is invalid: must be " + adhesionChoices());
}

K2Interpolation parseK2Interpolation(const std::string& s)
{
	if (s == "linear") return K2Interpolation::Linear;
	if (s == "sqrt") return K2Interpolation::Sqrt;
	throw std::invalid_argument("k2Interpolation = '" + s + "' is invalid: must be 'linear' or 'sqrt'");
}

const char* adhesionName(Adhesion a)
{
	const int k = static_cast<int>(a);
	return k >= 0 && k < kAdhesionModeCount ? kAdhesionModes[k].name : "none";
}

const char* k2InterpolationName(K2Interpolation k) { return k == K2Interpolation::Sqrt ? "sqrt" : "linear"; }

void validate(const MaterialParams& m)
{
	// Each number against its own rule (MesoParamTable.hpp), in the table's order.
#define MESO_CHECK(name, def, unit, ok, rule, ...)                                                                                                             \
	{                                                                                                                                                      \
		const double v = m.name;                                                                                                                       \
		finite(#name, v);                                                                                                                              \
		if (!(ok)) reject(#name, v, rule);                                                                                                             \
	}
	MESO_ALL_PARAMS(MESO_CHECK)
#undef MESO_CHECK
	if (m.fa > 0 && !(m.kca > 0)) reject("kca", m.kca, "must be > 0 when fa > 0 (the range of the non-contact force is fa/kca)");
	if (m.fa > 0 && !std::isfinite(m.fa / m.kca)) reject("kca", m.kca, "too small for fa: the range fa/kca of the non-contact force must be finite");
	if (m.fa > 0 && m.adhesion == Adhesion::None)
		throw std::invalid_argument("adhesion = 'none' is invalid with fa > 0: choose 'reversible' or 'jumpIn', or set fa = 0");
	finite("muS", m.muS);
	if (!(m.muS >= 0)) reject("muS", m.muS, "must be >= 0");
}

void validatePair(const PairParams& p)
{
	const int adhesion = static_cast<int>(p.adhesion), interp = static_cast<int>(p.k2Interpolation);
	if (adhesion < 0 || adhesion >= kAdhesionModeCount) {
		std::string modes;
		for (int k = 0; k < kAdhesionModeCount; ++k)
			modes += (k ? ", " : "") + std::to_string(k) + " " + kAdhesionModes[k].name;
		reject("adhesion", adhesion, ("must be a mode: " + modes).c_str());
	}
	if (interp < 0 || interp > 1) reject("k2Interpolation", interp, "must be 0 linear or 1 sqrt");
	MaterialParams m;
#define MESO_COPY(name, def, unit, ok, rule, mix, dest, ...) m.name = p.dest;
	MESO_ALL_PARAMS(MESO_COPY)
#undef MESO_COPY
	m.muS             = p.sliding.muS;
	m.adhesion        = p.adhesion;
	m.k2Interpolation = p.k2Interpolation;
	validate(m);
	for (const auto& [name, e] :
	     { std::make_pair("sliding muD", &p.sliding), std::make_pair("rolling muD", &p.rolling), std::make_pair("torsion muD", &p.torsion) }) {
		finite(name, e->muD);
		if (!(e->muD >= 0)) reject(name, e->muD, "must be >= 0");
	}
	if (!(p.leverFactor == 1 || p.leverFactor == 2)) reject("leverFactor", p.leverFactor, "must be 1 (reduced) or 2 (a12)");
	if (p.deltaA != ((p.fa > 0 && p.adhesion != Adhesion::None) ? -p.fa / p.kca : 0.0)) reject("deltaA", p.deltaA, "must be -fa/kca");
	if (p.delta0PerMaxP != (p.kp > p.k1 ? 1 - p.k1 / p.kp : 0.0)) reject("delta0PerMaxP", p.delta0PerMaxP, "must be 1 - k1/kp");
	const bool any = p.sliding.active() || p.rolling.active() || p.torsion.active();
	if (p.tangential != any || p.slidingActs != p.sliding.active() || (p.rollingActs && !p.rolling.active()) || (p.torsionActs && !p.torsion.active())
	    || (p.rollingOrTorsion && !(p.rolling.active() || p.torsion.active())))
		throw std::invalid_argument("tangential flags are invalid: they must follow the elements (setMechanisms)");
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
	p.tangential       = p.sliding.active() || p.rolling.active() || p.torsion.active();
	p.rollingOrTorsion = (p.rolling.active() || p.torsion.active()) && geometryWithRotations;
	p.slidingActs      = p.sliding.active();
	p.rollingActs      = p.rollingOrTorsion && p.rolling.active();
	p.torsionActs      = p.rollingOrTorsion && p.torsion.active();
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

namespace {
	// The mixing rules of MesoParamTable.hpp.
	double harmonic(double x, double y) { return harmonicMean(x, y); }
	double arithmetic(double x, double y) { return 0.5 * (x + y); }
	double smaller(double x, double y) { return std::min(x, y); }
}

std::string firstDifference(const PairParams& a, const PairParams& b)
{
#define MESO_DIFF(name, def, unit, ok, rule, mix, dest, ...)                                                                                                   \
	if (a.dest != b.dest) return #name;
	MESO_ALL_PARAMS(MESO_DIFF)
#undef MESO_DIFF
	if (a.adhesion != b.adhesion) return "adhesion";
	if (a.k2Interpolation != b.k2Interpolation) return "k2Interpolation";
	for (const auto& [name, x, y] : { std::make_tuple("sliding", &a.sliding, &b.sliding),
	                                  std::make_tuple("rolling", &a.rolling, &b.rolling),
	                                  std::make_tuple("torsion", &a.torsion, &b.torsion) })
		if (x->k != y->k || x->gamma != y->gamma || x->muS != y->muS || x->muD != y->muD) return std::string(name) + " element";
	if (a.tangential != b.tangential || a.rollingOrTorsion != b.rollingOrTorsion) return "the tangential mechanisms";
	if (a.leverFactor != b.leverFactor) return "leverFactor";
	return "";
}

PairParams mixPair(const MaterialParams& mat1, const MaterialParams& mat2)
{
	const bool            one = mat1.dominant && !mat2.dominant, two = mat2.dominant && !mat1.dominant;
	const MaterialParams& m1 = two ? mat2 : mat1;
	const MaterialParams& m2 = one ? mat1 : mat2;
	PairParams            p;
#define MESO_MIX(name, def, unit, ok, rule, mix, dest, ...) p.dest = mix(m1.name, m2.name);
	MESO_ALL_PARAMS(MESO_MIX)
#undef MESO_MIX
	p.kp              = std::max(p.kp, p.k1); // the harmonic mean is monotone, so kp >= k1 holds up to rounding
	p.adhesion        = adhesionMode(m1.adhesion).strength <= adhesionMode(m2.adhesion).strength ? m1.adhesion : m2.adhesion;
	p.k2Interpolation = (m1.k2Interpolation == K2Interpolation::Sqrt && m2.k2Interpolation == K2Interpolation::Sqrt) ? K2Interpolation::Sqrt
	                                                                                                                 : K2Interpolation::Linear;
	if (p.adhesion == Adhesion::None) p.fa = 0;
	p.sliding.muS = smaller(m1.muS, m2.muS);
	for (ElementParams* e : { &p.sliding, &p.rolling, &p.torsion })
		e->muD = p.phiD * e->muS;
	p.deltaA        = (p.fa > 0 && p.adhesion != Adhesion::None) ? -p.fa / p.kca : 0.0;
	p.delta0PerMaxP = p.kp > p.k1 ? 1 - p.k1 / p.kp : 0.0;
	return p;
}

} // namespace meso
