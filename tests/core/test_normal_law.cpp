// Every branch and transition of the hysteretic normal law, the adhesion modes and the energy
// bookkeeping, against values derived by hand from docs/model.md §3–5 (not from the code under test).
#include "NormalLaw.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace meso;

namespace {
// A pair of equal spheres of radius a12 (so that their reduced radius is a12).
struct Pair {
	PairParams   p;
	PairGeometry g;
};
Pair pairOf(const MaterialParams& m, double a12 = 1e-3)
{
	const PairParams p = mixPair(m, m);
	return { p, pairGeometry(p, a12, a12) };
}
Pair pair(double k1 = 100, double kp = 500, double kc = 100, double phiF = 0.1, double a12 = 1e-3, K2Interpolation interp = K2Interpolation::Linear)
{
	MaterialParams m;
	m.k1              = k1;
	m.kp              = kp;
	m.kc              = kc;
	m.phiF            = phiF;
	m.k2Interpolation = interp;
	return pairOf(m, a12);
}
double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }
}

TEST(Geometry, LimitOverlapAndPlasticDepth)
{
	const auto [p, g] = pair();
	EXPECT_NEAR(g.delta0P(p), 1e-4, 1e-18);
	EXPECT_NEAR(g.deltaMaxP(), 500.0 / 400.0 * 1e-4, 1e-18); // Eq. 10
}

TEST(Hysteresis, VirginLoadingFollowsK1)
{
	const auto [p, g] = pair();
	NormalHistory h;
	for (double d = 1e-6; d < g.deltaMaxP(); d += 1e-6) {
		EXPECT_NEAR(hystereticForce(p, g, h, d), 100 * d, 1e-12);
		EXPECT_DOUBLE_EQ(h.deltaMax, d);
	}
}

TEST(Hysteresis, UnloadingAndReloadingFollowK2Line)
{
	const auto [p, g] = pair();
	NormalHistory h;
	const double  dm = 0.5 * g.deltaMaxP();
	hystereticForce(p, g, h, dm);
	const double k2 = 100 + 400 * 0.5, d0 = (1 - 100 / k2) * dm; // Eqs. 9, 7
	EXPECT_NEAR(unloadingStiffness(p, g, h), k2, 1e-12);
	EXPECT_NEAR(h.delta0, d0, 1e-18);
	for (double d : { 0.9 * dm, 0.7 * dm, 0.8 * dm, 0.95 * dm })
		EXPECT_NEAR(hystereticForce(p, g, h, d), k2 * (d - d0), 1e-12) << d;
	EXPECT_DOUBLE_EQ(h.deltaMax, dm);                                       // re-loading below deltaMax keeps the history
	EXPECT_NEAR(hystereticForce(p, g, h, 1.1 * dm), 100 * 1.1 * dm, 1e-12); // past deltaMax: back on k1
}

TEST(Hysteresis, LimitBranchBeyondDeltaMaxP)
{
	const auto [p, g] = pair();
	NormalHistory h;
	EXPECT_NEAR(hystereticForce(p, g, h, g.deltaMaxP()), 100 * g.deltaMaxP(), 1e-12); // continuous at the transition
	for (double d : { 1.2 * g.deltaMaxP(), 2 * g.deltaMaxP(), 1.5 * g.deltaMaxP() })  // loading, then unloading on kp
		EXPECT_NEAR(hystereticForce(p, g, h, d), 500 * (d - g.delta0P(p)), 1e-12);
	EXPECT_DOUBLE_EQ(unloadingStiffness(p, g, h), 500);
	EXPECT_DOUBLE_EQ(h.delta0, g.delta0P(p));
}

TEST(Hysteresis, TensileLimitReachedAtDeltaMin)
{
	const auto [p, g] = pair();
	NormalHistory h;
	const double  dm = 0.6 * g.deltaMaxP();
	hystereticForce(p, g, h, dm);
	const double k2 = unloadingStiffness(p, g, h), dmin = (k2 - 100) / (k2 + 100) * dm;         // Eq. 8
	EXPECT_NEAR(hystereticForce(p, g, h, dmin * 1.001), k2 * (dmin * 1.001 - h.delta0), 1e-12); // still on k2
	EXPECT_DOUBLE_EQ(h.deltaMax, dm);
	const double d = 0.5 * dmin;
	EXPECT_NEAR(hystereticForce(p, g, h, d), -100 * d, 1e-15); // on -kc
	EXPECT_LT(h.deltaMax, dm);                                 // history reset
}

TEST(Hysteresis, KcResetIsExactLinear)
{
	const auto [p, g] = pair();
	NormalHistory h;
	hystereticForce(p, g, h, 0.8 * g.deltaMaxP());
	const double d = 0.05 * g.deltaMaxP();
	hystereticForce(p, g, h, d);
	// The new line passes through (d, -kc d): k2'(d - d0') = -kc d, with k2', d0' from Eqs. 9, 7 of the new deltaMax.
	const double dm = h.deltaMax, k2 = 100 + 400 * dm / g.deltaMaxP(), d0 = (1 - 100 / k2) * dm;
	EXPECT_LT(rel(k2 * (d - d0), -100 * d), 1e-12);
	// Re-loading from there follows that line, not the old one.
	const double d2 = 1.5 * d;
	EXPECT_LT(rel(hystereticForce(p, g, h, d2), k2 * (d2 - d0)), 1e-12);
}

TEST(Hysteresis, KcResetContinuousWithLimitBranch)
{
	const auto [p, g] = pair();
	NormalHistory h;
	const double  dStar = 500 * g.delta0P(p) / (500 + 100); // kp delta0P/(kp + kc)
	EXPECT_LT(rel(deltaMaxThrough(p, g, dStar), g.deltaMaxP()), 1e-12);
}

TEST(Hysteresis, SqrtInterpolationAndItsReset)
{
	const auto [p, g] = pair(100, 500, 100, 0.1, 1e-3, K2Interpolation::Sqrt);
	NormalHistory h;
	const double  dm = 0.3 * g.deltaMaxP();
	hystereticForce(p, g, h, dm);
	EXPECT_NEAR(unloadingStiffness(p, g, h), 100 * (1 + 4 * std::sqrt(0.3)), 1e-10); // Eq. D.1
	// Reset along -kc at several overlaps: the root must satisfy (k2 - k1) dm' = (k2 + kc) d.
	for (double x : { 1e-6, 1e-3, 0.01, 0.1, 0.3, 0.5, 0.8333333 }) {
		const double d = x * g.deltaMaxP(), dm2 = deltaMaxThrough(p, g, d);
		const double k2 = 100 * (1 + 4 * std::sqrt(dm2 / g.deltaMaxP()));
		EXPECT_LT(rel((k2 - 100) * dm2, (k2 + 100) * d), 1e-12) << x;
	}
	EXPECT_NEAR(hystereticForce(p, g, h, g.deltaMaxP() * 1.2), 500 * (1.2 * g.deltaMaxP() - g.delta0P(p)), 1e-12);
}

TEST(Hysteresis, SeparationResetsHistory)
{
	const auto [p, g] = pair();
	NormalHistory h;
	hystereticForce(p, g, h, 0.5 * g.deltaMaxP());
	EXPECT_EQ(hystereticForce(p, g, h, -1e-9), 0.0);
	EXPECT_EQ(h.deltaMax, 0.0);
	EXPECT_NEAR(hystereticForce(p, g, h, 1e-6), 100 * 1e-6, 1e-15); // a new contact starts on k1
}

TEST(Hysteresis, LinearSpringWhenKpEqualsK1)
{
	const auto [p, g] = pair(100, 100, 0);
	NormalHistory h;
	EXPECT_TRUE(std::isinf(g.deltaMaxP()));
	for (double d : { 1e-5, 3e-4, 1e-4, 2e-3, 1e-6 })
		EXPECT_DOUBLE_EQ(hystereticForce(p, g, h, d), 100 * d);
}

TEST(Adhesion, ReversibleProfile)
{
	MaterialParams m;
	m.fa                               = 1e-3;
	m.kca                              = 10;
	m.adhesion                         = Adhesion::Reversible;
	[[maybe_unused]] const auto [p, g] = pairOf(m);
	NormalHistory h;
	EXPECT_DOUBLE_EQ(p.deltaA, -1e-4);
	EXPECT_EQ(adhesiveForce(p, h, -2e-4), 0.0);
	EXPECT_NEAR(adhesiveForce(p, h, -0.5e-4), -10 * -0.5e-4 - 1e-3, 1e-18); // pull-in acts before touch
	EXPECT_DOUBLE_EQ(adhesiveForce(p, h, 1e-5), -1e-3);
	EXPECT_TRUE(keepsInteracting(p, -0.9e-4));
	EXPECT_FALSE(keepsInteracting(p, -1.1e-4));
}

TEST(Adhesion, JumpInActsOnlyAfterFirstTouch)
{
	MaterialParams m;
	m.fa                               = 1e-3;
	m.kca                              = 10;
	m.adhesion                         = Adhesion::JumpIn;
	[[maybe_unused]] const auto [p, g] = pairOf(m);
	NormalHistory h;
	EXPECT_EQ(adhesiveForce(p, h, -0.5e-4), 0.0);
	EXPECT_FALSE(h.touched);
	EXPECT_DOUBLE_EQ(adhesiveForce(p, h, 1e-6), -1e-3); // jump to -fa at contact
	EXPECT_TRUE(h.touched);
	EXPECT_NEAR(adhesiveForce(p, h, -0.5e-4), 5e-4 - 1e-3, 1e-18); // pull-off tail
}

TEST(Adhesion, RecomputedFromTheHistoryItLeft)
{
	// A contact keeps no adhesive force: adhesiveForceAfter() must give what adhesiveForce() gave.
	for (Adhesion mode : { Adhesion::None, Adhesion::Reversible, Adhesion::JumpIn }) {
		MaterialParams m;
		m.fa                               = 1e-3;
		m.kca                              = 10;
		m.adhesion                         = mode;
		[[maybe_unused]] const auto [p, g] = pairOf(m);
		NormalHistory h;
		for (double d : { -2e-4, -0.5e-4, -1e-6, 1e-6, 3e-5, -1e-6, -0.5e-4, -0.99e-4, 1e-7, -2e-4 }) {
			const double f = adhesiveForce(p, h, d);
			EXPECT_EQ(adhesiveForceAfter(p, h, d), f) << adhesionName(mode) << " at " << d;
		}
	}
}

TEST(Viscous, OnlyInMechanicalContact)
{
	MaterialParams m;
	m.gammaN                           = 2e-3;
	[[maybe_unused]] const auto [p, g] = pairOf(m);
	NormalHistory h;
	EXPECT_DOUBLE_EQ(normalForce(p, g, h, 1e-6, 0.5).viscous, 1e-3);
	EXPECT_EQ(normalForce(p, g, h, -1e-6, 0.5).viscous, 0.0);
}

TEST(Viscous, QuadraticDashpotGrowsWithTheSquareAndOpposesTheMotion)
{
	// gammaN2 |vn| vn beside gammaN vn: 2e-3 x 0.5 + 4e-2 x 0.25 = 1.1e-2 N approaching, the opposite leaving.
	MaterialParams m;
	m.gammaN                           = 2e-3;
	m.gammaN2                          = 4e-2;
	[[maybe_unused]] const auto [p, g] = pairOf(m);
	NormalHistory h;
	EXPECT_DOUBLE_EQ(normalForce(p, g, h, 1e-6, 0.5).viscous, 1.1e-2);
	EXPECT_DOUBLE_EQ(normalForce(p, g, h, 1e-6, -0.5).viscous, -1.1e-2);
	EXPECT_EQ(normalForce(p, g, h, -1e-6, 0.5).viscous, 0.0);
	m.gammaN                            = 0;
	[[maybe_unused]] const auto [q, g2] = pairOf(m);
	EXPECT_DOUBLE_EQ(normalForce(q, g2, h, 1e-6, 2.0).viscous, 4 * normalForce(q, g2, h, 1e-6, 1.0).viscous);
}

TEST(Viscous, WithoutTheQuadraticDashpotTheForceIsTheLinearOneBitForBit)
{
	// gammaN2 = 0 (the default) must leave every earlier result as it was: gammaN vn to the last bit.
	MaterialParams m;
	m.gammaN                           = 1.2345678901234567e-3;
	[[maybe_unused]] const auto [p, g] = pairOf(m);
	NormalHistory h;
	for (const double vn : { 0.3, -7.77, 1e-9, 123.456 })
		EXPECT_EQ(normalForce(p, g, h, 1e-6, vn).viscous, 1.2345678901234567e-3 * vn) << vn;
}

TEST(Viscous, NotInTheNonContactRange)
{
	// Reversible adhesion acts down to deltaA = -fa/kca = -1e-6 m; the dashpot only in contact. A
	// dashpot acting wherever the pair interacts would give gammaN vn = 1e-3 N here.
	MaterialParams m;
	m.gammaN                           = 2e-3;
	m.fa                               = 1e-4;
	m.kca                              = 100;
	m.adhesion                         = Adhesion::Reversible;
	[[maybe_unused]] const auto [p, g] = pairOf(m);
	for (const Adhesion mode : { Adhesion::Reversible, Adhesion::JumpIn }) {
		PairParams q = p;
		q.adhesion   = mode;
		NormalHistory h;
		h.touched           = true;
		const NormalForce f = normalForce(q, g, h, -0.5e-6, 0.5);
		EXPECT_DOUBLE_EQ(f.adhesive, -100 * -0.5e-6 - 1e-4) << adhesionName(mode); // inside the range: the law acts ...
		EXPECT_EQ(f.viscous, 0.0) << adhesionName(mode);                           // ... but not the dashpot
	}
}

// delta = D + A sin(w t), vn = A w cos(w t) over a quarter period, in n steps: what energyStep books as viscous.
constexpr double kD = 2e-5, kA = 1e-5, kW = 1e3;
double           viscousAlongQuarterPeriod(const MaterialParams& m, int n = 1000)
{
	[[maybe_unused]] const auto [p, g] = pairOf(m);
	const double  T                    = M_PI / (2 * kW);
	NormalHistory h;
	NormalForce   prev    = normalForce(p, g, h, kD, kA * kW);
	double        viscous = 0, prevDelta = kD, prevElastic = storedElastic(p, g, h, prev.hysteretic);
	for (int i = 1; i <= n; ++i) {
		const double      t = T * i / n, d = kD + kA * std::sin(kW * t);
		const NormalForce f = normalForce(p, g, h, d, kA * kW * std::cos(kW * t));
		viscous += energyStep(p, g, prevDelta, prevElastic, h, prev, f, d).viscous;
		prev        = f;
		prevDelta   = d;
		prevElastic = storedElastic(p, g, h, f.hysteretic);
	}
	return viscous;
}

TEST(Energy, ViscousDissipationOfAHarmonicPathIsItsIntegral)
{
	// The dashpot dissipates int gammaN vn d(delta) = gammaN A^2 w pi/4. The trapezoid of energyStep is
	// exact to O(h^2) (4.1e-7 here, n = 1000); a rectangle rule is off by O(h), 5.0e-4.
	MaterialParams m;
	m.gammaN = 2e-3;
	EXPECT_LT(rel(viscousAlongQuarterPeriod(m), 2e-3 * kA * kA * kW * M_PI / 4), 1e-5);
}

TEST(Energy, QuadraticDashpotDissipationOfAHarmonicPathIsItsIntegral)
{
	// The same path with gammaN2 alone: int gammaN2 vn^3 dt over the quarter period = gammaN2 A^3 w^2 (2/3).
	MaterialParams m;
	m.gammaN2 = 5e-2;
	EXPECT_LT(rel(viscousAlongQuarterPeriod(m), 5e-2 * kA * kA * kA * kW * kW * 2 / 3), 1e-5);
}

TEST(Energy, LoopDissipationEqualsEnclosedArea)
{
	// Load on k1 to dm, unload on k2 to delta0: dissipated = 1/2 k1 dm^2 - 1/2 k2 (dm - d0)^2.
	const auto [p, g] = pair(100, 500, 0);
	NormalHistory h;
	NormalForce   prev;
	const double  dm      = 0.7 * g.deltaMaxP();
	const int     n       = 2000;
	double        plastic = 0, prevDelta = 0, prevElastic = 0;
	for (int i = 1; i <= n; ++i) { // fine steps: the trapezoid is exact on each linear piece
		const double d = dm * i / n;
		NormalForce  f = normalForce(p, g, h, d, 0);
		plastic += energyStep(p, g, prevDelta, prevElastic, h, prev, f, d).plastic;
		prev        = f;
		prevDelta   = d;
		prevElastic = storedElastic(p, g, h, f.hysteretic);
	}
	const double k2 = unloadingStiffness(p, g, h), d0 = h.delta0;
	for (int i = 1; i <= n; ++i) {
		const double d = dm - (dm - d0) * i / n;
		NormalForce  f = normalForce(p, g, h, d, 0);
		plastic += energyStep(p, g, prevDelta, prevElastic, h, prev, f, d).plastic;
		prev        = f;
		prevDelta   = d;
		prevElastic = storedElastic(p, g, h, f.hysteretic);
	}
	const double expected = 0.5 * 100 * dm * dm - 0.5 * k2 * (dm - d0) * (dm - d0);
	EXPECT_LT(rel(plastic, expected), 1e-9);
	EXPECT_LT(storedElastic(p, g, h, prev.hysteretic), 1e-20);
}

// branchAfter reads the branch back from what a step left: a path through every branch, each step
// classified against where the path is by construction (dmp = 1.25e-4 m here).
TEST(Branch, EveryBranchOfAPath)
{
	MaterialParams m;
	m.k1        = 100;
	m.kp        = 500;
	m.kc        = 100;
	m.phiF      = 0.1;
	m.fa        = 1e-6;
	m.kca       = 100;
	m.adhesion  = Adhesion::Reversible;
	auto [p, g] = pairOf(m);
	NormalHistory h;
	auto          step = [&](double delta) {
                const NormalForce f = normalForce(p, g, h, delta, 0.0);
                return branchAfter(p, g, h, delta, f.hysteretic);
	};
	EXPECT_EQ(branchAfter(p, g, h, std::nan(""), 0.0), Branch::New);
	EXPECT_EQ(step(-5e-9), Branch::NonContact);  // inside the pull-in range fa/kca = 1e-8 m
	EXPECT_EQ(step(-2e-6), Branch::Apart);       // beyond it
	EXPECT_EQ(step(5e-5), Branch::Loading);      // k1, below deltaMaxP
	EXPECT_EQ(step(1.5e-4), Branch::Limit);      // beyond deltaMaxP
	EXPECT_EQ(step(1.4e-4), Branch::Unloading);  // back along the kp line (delta0 = 1e-4)
	EXPECT_EQ(step(1.45e-4), Branch::Unloading); // re-loading below deltaMax
	EXPECT_EQ(step(5e-5), Branch::Tensile);      // the kp line gives -250e-4 N < -kc delta = -50e-4 N
	EXPECT_EQ(step(4e-5), Branch::Tensile);      // still along -kc delta
	EXPECT_EQ(step(2e-4), Branch::Limit);        // loaded again beyond every deltaMax
	EXPECT_EQ(step(-2e-6), Branch::Apart);
	EXPECT_STREQ(branchName(Branch::NonContact), "nonContact");
	EXPECT_STREQ(branchName(Branch::Tensile), "tensile");
}
