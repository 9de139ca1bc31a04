#include "MesoParams.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

using namespace meso;

namespace {
std::string rejection(const MaterialParams& m)
{
	try {
		validate(m);
	} catch (const std::invalid_argument& e) {
		return e.what();
	}
	return "";
}
bool startsWith(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }
}

TEST(Validate, DefaultsAreValid) { EXPECT_EQ(rejection(MaterialParams()), ""); }

TEST(Validate, EachRuleNamesItsParameter)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	struct Case {
		void (*set)(MaterialParams&);
		const char* name;
	};
	const Case cases[] = {
		{ [](MaterialParams& m) { m.kp   = 50; }, "kp" },
		{ [](MaterialParams& m) { m.k1= -1; }, "k1" },
		{ [](MaterialParams& m) { m.kc= -1; }, "kc" },
		{ [](MaterialParams& m) { m.phiF= 0; }, "phiF" },
		{ [](MaterialParams& m) { m.phiF= 1.5; }, "phiF" },
		{ [](MaterialParams& m) {
		         m.fa= 1e-3;
		         m.adhesion= Adhesion::Reversible;
		 },
		  "kca" },
		{ [](MaterialParams& m) { m.fa= -1; }, "fa" },
		{ [](MaterialParams& m) { m.gammaN= -1; }, "gammaN" },
		{ [](MaterialParams& m) { m.gammaN2= -1; }, "gammaN2" },
		{ [](MaterialParams& m) {
		         m.fa= 1e-3;
		         m.kca= 1;
		 },
		  "adhesion" },
		{ [](MaterialParams& m) { m.k1= std::numeric_limits<double>::quiet_NaN(); }, "k1" },
		{ [](MaterialParams& m) { m.kc= std::numeric_limits<double>::infinity(); }, "kc" },
	};
	(void)nan;
	for (const Case& c : cases) {
		MaterialParams m;
		c.set(m);
		const std::string msg = rejection(m);
		EXPECT_TRUE(startsWith(msg, c.name)) << c.name << ": '" << msg << "'";
	}
}

TEST(Validate, ModeNames)
{
	EXPECT_EQ(parseAdhesion("jumpIn"), Adhesion::JumpIn);
	EXPECT_EQ(parseK2Interpolation("sqrt"), K2Interpolation::Sqrt);
	EXPECT_THROW(parseAdhesion("jump-in"), std::invalid_argument);
	EXPECT_THROW(parseK2Interpolation("cubic"), std::invalid_argument);
}

TEST(Mixing, EqualMaterialsKeepTheirValues)
{
	MaterialParams m;
	m.k1               = 3;
	m.kp               = 7;
	m.kc               = 2;
	m.phiF             = 0.3;
	m.fa               = 1e-3;
	m.kca              = 5;
	m.gammaN           = 1e-2;
	m.adhesion         = Adhesion::JumpIn;
	m.k2Interpolation  = K2Interpolation::Sqrt;
	const PairParams p = mixPair(m, m);
	EXPECT_DOUBLE_EQ(p.k1, 3);
	EXPECT_DOUBLE_EQ(p.kp, 7);
	EXPECT_DOUBLE_EQ(p.kc, 2);
	EXPECT_DOUBLE_EQ(p.phiF, 0.3);
	EXPECT_DOUBLE_EQ(p.fa, 1e-3);
	EXPECT_DOUBLE_EQ(p.kca, 5);
	EXPECT_DOUBLE_EQ(p.gammaN, 1e-2);
	EXPECT_EQ(p.adhesion, Adhesion::JumpIn);
	EXPECT_EQ(p.k2Interpolation, K2Interpolation::Sqrt);
}

TEST(Mixing, UnlikeMaterials)
{
	MaterialParams a, b;
	a.k1               = 100;
	a.kp               = 500;
	b.k1               = 300;
	b.kp               = 300;
	a.adhesion         = Adhesion::Reversible;
	a.fa               = 1e-3;
	a.kca              = 1;
	const PairParams p = mixPair(a, b);
	EXPECT_DOUBLE_EQ(p.k1, 150);
	EXPECT_DOUBLE_EQ(p.kp, 375);
	EXPECT_GE(p.kp, p.k1);
	EXPECT_EQ(p.adhesion, Adhesion::None); // b has none
	EXPECT_EQ(p.fa, 0.0);
	EXPECT_EQ(p.deltaA, 0.0);
}

TEST(Geometry, ReducedRadiusAndLimitOverlapPerContact)
{
	MaterialParams m;
	m.k1               = 100;
	m.kp               = 500;
	m.phiF             = 0.1;
	const PairParams p = mixPair(m, m);
	EXPECT_DOUBLE_EQ(pairGeometry(p, 1e-3, 3e-3).a12(), 1.5e-3); // 2 a1 a2/(a1 + a2)
	EXPECT_DOUBLE_EQ(pairGeometry(p, 1e-3, 0).a12(), 2e-3);      // against a wall: 2 a
	EXPECT_DOUBLE_EQ(pairGeometry(p, 0, 1e-3).a12(), 2e-3);
	const PairGeometry g = pairGeometry(p, 1e-3, 0);
	EXPECT_DOUBLE_EQ(g.deltaMaxP(), 500.0 / 400.0 * 0.1 * 2e-3); // Eq. 10
	EXPECT_DOUBLE_EQ(g.invDeltaMaxP * g.deltaMaxP(), 1);
	EXPECT_DOUBLE_EQ(g.delta0P(p), 0.1 * 2e-3); // Eq. 11
	EXPECT_NEAR(p.delta0PerMaxP * g.deltaMaxP(), g.delta0P(p), 1e-19);
}

TEST(Mixing, DominantMaterialImposesItsParameters)
{
	MaterialParams particle, wall;
	particle.k1   = 2.5;
	particle.kp   = 5;
	particle.kc   = 1;
	particle.muS  = 1;
	wall.k1       = 2.5;
	wall.kp       = 5;
	wall.kc       = 100;
	wall.muS      = 10;
	wall.dominant = true;
	for (const PairParams& p : { mixPair(particle, wall), mixPair(wall, particle) }) {
		EXPECT_DOUBLE_EQ(p.kc, 100); // the harmonic mean would give 2*1*100/101
		EXPECT_DOUBLE_EQ(p.sliding.muS, 10);
		EXPECT_DOUBLE_EQ(p.kp, 5);
	}
	particle.dominant = true; // both dominant: mixed as usual
	EXPECT_DOUBLE_EQ(mixPair(particle, wall).kc, 200.0 / 101.0);
	EXPECT_DOUBLE_EQ(mixPair(particle, wall).sliding.muS, 1);
}

TEST(Mixing, HarmonicMeanOfExtremeValuesStaysFinite)
{
	// 2xy/(x+y) overflows from ~1e154 on; the mean lies between x and y, so it never may.
	const double big = std::numeric_limits<double>::max();
	EXPECT_EQ(harmonicMean(big, big), big);
	EXPECT_DOUBLE_EQ(harmonicMean(1e155, 3e155), 1.5e155);
	EXPECT_DOUBLE_EQ(harmonicMean(1.5e308, 1.7e308), 2 / (1 / 1.5e308 + 1 / 1.7e308));
	EXPECT_DOUBLE_EQ(harmonicMean(1e-300, 3e-300), 1.5e-300);
	EXPECT_EQ(harmonicMean(7.25, 7.25), 7.25); // equal materials keep their value exactly
	EXPECT_EQ(harmonicMean(0, big), 0.0);
	MaterialParams m;
	m.k1 = m.kp        = 1e155;
	const PairParams p = mixPair(m, m);
	EXPECT_EQ(p.k1, 1e155);
	EXPECT_EQ(p.kp, 1e155);
}

TEST(Validate, ValuesBeyondTheLawsProductsAreNamed)
{
	// k1 = kp = 1e200 made f^2/k overflow, fa = 1e300 infinite accelerations, kp = 1e308 a stable step 0.
	MaterialParams m;
	m.adhesion = Adhesion::Reversible;
	m.fa       = 1e300;
	m.kca      = 1e-300;
	EXPECT_TRUE(startsWith(rejection(m), "fa = 1.0000000000000001e+300 is invalid: lies outside [1e-100, 1e100]")) << rejection(m);
	MaterialParams k;
	k.k1 = k.kp = 1e200;
	EXPECT_TRUE(startsWith(rejection(k), "k1 = 9.9999999999999997e+199")) << rejection(k);
	MaterialParams t;
	t.kt = 1e-300;
	EXPECT_TRUE(startsWith(rejection(t), "kt = 1e-300")) << rejection(t);
	MaterialParams edge;
	edge.k1 = 1e-100;
	edge.kp = 1e100;
	edge.kc = 0; // the limits themselves and 0 pass
	EXPECT_EQ(rejection(edge), "");
}

TEST(StableStep, SpringDashpotBounds)
{
	const double m = 2e-3, k = 500;
	EXPECT_DOUBLE_EQ(stableStep(k, 0, 1 / m), 2 * std::sqrt(m / k));
	EXPECT_DOUBLE_EQ(stableStep(0, 0.1, 1 / m), 2 * m / 0.1);
	EXPECT_TRUE(std::isinf(stableStep(k, 0, 0))); // a body that does not move
	// omega^2 dt^2 + 2 gamma dt / m = 4 at the bound (the leapfrog's eigenvalue -1)
	const double g = 3e-2, dt = stableStep(k, g, 1 / m);
	EXPECT_NEAR(k / m * dt * dt + 2 * g * dt / m, 4, 1e-12);
}
