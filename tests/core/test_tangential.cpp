// The spring-dashpot-Coulomb element, the rotation of springs with the contact and the contact
// kinematics, against hand-derived values (docs/tangential.md).
#include "Tangential.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace meso;

namespace {
ElementParams element(double k, double gamma, double muS, double muD)
{
	ElementParams e;
	e.k     = k;
	e.gamma = gamma;
	e.muS   = muS;
	e.muD   = muD;
	return e;
}
}

TEST(Element, SticksBelowTheStaticLimit)
{
	const ElementParams p       = element(100, 0.5, 1.0, 0.8);
	Vec3                xi      = Vec3::Zero();
	bool                sliding = false;
	const Vec3          v(1e-3, 0, 0);
	for (int i = 1; i <= 10; ++i) {
		const auto s = elementStep(p, xi, v, 1e-3, 1.0, sliding);
		EXPECT_FALSE(s.slipped);
		EXPECT_NEAR(s.force.x(), -100 * 1e-6 * i - 0.5e-3, 1e-15); // -k (i v dt) - gamma v
	}
}

TEST(Element, SlipsAtTheDynamicLimitAndResumesWithoutJump)
{
	const ElementParams p = element(100, 0.0, 1.0, 0.8);
	Vec3                xi(0.0, -0.02, 0); // trial |f| = 2 > muS level = 1
	bool                sliding = false;
	const auto          s       = elementStep(p, xi, Vec3(Vec3::Zero()), 1e-3, 1.0, sliding);
	EXPECT_TRUE(s.slipped);
	EXPECT_NEAR(s.force.norm(), 0.8, 1e-15);             // muD level
	EXPECT_NEAR(s.force.y(), 0.8, 1e-15);                // along the trial direction
	EXPECT_NEAR((-p.k * xi - s.force).norm(), 0, 1e-15); // spring reset: next trial equals f
	const auto again = elementStep(p, xi, Vec3(Vec3::Zero()), 1e-3, 1.0, sliding);
	EXPECT_FALSE(again.slipped); // at rest the trial equals the dynamic limit: it sticks
	EXPECT_NEAR(again.force.y(), 0.8, 1e-15);
}

TEST(Element, KeepsSlidingAtTheDynamicLimit)
{
	const ElementParams p = element(100, 0.0, 1.0, 0.8);
	Vec3                xi(0.0, -0.0101, 0); // just beyond the static limit
	bool                sliding = false;
	const Vec3          v(0, -1e-3, 0); // keeps moving against the force (+y)
	for (int i = 0; i < 100; ++i) {
		const auto s = elementStep(p, xi, v, 1e-3, 1.0, sliding);
		EXPECT_TRUE(s.slipped) << i; // trial = 0.8 + k v dt > muD level: still sliding
		EXPECT_NEAR(s.force.norm(), 0.8, 1e-15);
	}
}

TEST(Element, ScalarTorsion)
{
	const ElementParams p       = element(10, 0, 0.5, 0.5);
	double              xi      = 0;
	bool                sliding = false;
	for (int i = 0; i < 1000; ++i)
		elementStep(p, xi, 1.0, 1e-3, 2.0, sliding);
	EXPECT_NEAR(-p.k * xi, -1.0, 1e-12); // capped at mu level = 1
}

TEST(Element, NoSpringNoDivision)
{
	const ElementParams p       = element(0, 1.0, 0.1, 0.1);
	Vec3                xi      = Vec3::Zero();
	bool                sliding = false;
	const auto          s       = elementStep(p, xi, Vec3(1, 0, 0), 1e-3, 1.0, sliding);
	EXPECT_NEAR(s.force.x(), -0.1, 1e-15);
	EXPECT_TRUE(xi.allFinite());
}

TEST(Rotation, SpringFollowsTheNormal)
{
	const Vec3   n0(1, 0, 0);
	const double th = 0.3;
	const Vec3   n1(std::cos(th), std::sin(th), 0);
	Vec3         xi(0, 2e-3, 5e-4);
	rotateWithContact(xi, n0, n1, 0);
	EXPECT_NEAR(xi.dot(n1), 0, 1e-18);
	EXPECT_NEAR(xi.x(), -2e-3 * std::sin(th), 1e-15); // rotated about z by th
	EXPECT_NEAR(xi.y(), 2e-3 * std::cos(th), 1e-15);
	EXPECT_NEAR(xi.z(), 5e-4, 1e-15);
	for (double spin : { 1e-3, 0.5 * M_PI }) { // a step's spin about n: exactly 2 atan(spin/2), length kept
		Vec3 xi2(0, 0, 1);                 // perpendicular to n1
		rotateWithContact(xi2, n1, n1, spin);
		const double angle = 2 * std::atan(0.5 * spin);
		EXPECT_NEAR(xi2.norm(), 1, 1e-15);
		EXPECT_NEAR(xi2.dot(n1.cross(Vec3(0, 0, 1))), std::sin(angle), 1e-15);
		EXPECT_NEAR(xi2.z(), std::cos(angle), 1e-15);
	}
}

TEST(Kinematics, RigidRotationHasNoRelativeMotion)
{
	// Two spheres (radii 1 and 2, overlap 0.1) rotating rigidly with w about an arbitrary axis.
	const Vec3              w(0.3, -0.7, 0.2), x1(0, 0, 0);
	const double            a1 = 1, a2 = 2, delta = 0.1, d = a1 + a2 - delta;
	const Vec3              n = Vec3(1, 2, 2).normalized(), x2 = x1 + d * n;
	const Vec3              v1 = w.cross(x1), v2 = w.cross(x2);
	const Vec3              vc = sphereContactVelocity(n, v1 - v2, w, w, a1 - delta / 2, a2 - delta / 2);
	const ContactVelocities c  = contactVelocities(n, vc, w - w, 0.6);
	EXPECT_NEAR(c.sliding.norm(), 0, 1e-15);
	EXPECT_NEAR(c.rolling.norm(), 0, 1e-15);
	EXPECT_NEAR(c.torsion, 0, 1e-15);
}

TEST(Kinematics, ArmsOfUnequalSpheres)
{
	// Radii 1 and 3 mm, overlap 10 um: the arms are a - delta/2 each, the lever arm of rolling and
	// torsion a1'a2'/(a1'+a2') (leverFactor 1) or twice that (2); against a wall the sphere's arm.
	// (For equal spheres a mean of the arms would give the same lever: only unequal ones tell.)
	PairParams   p;
	PairGeometry g;
	g.radius1       = 1e-3;
	g.radius2       = 3e-3;
	const double a1 = 0.995e-3, a2 = 2.995e-3, reduced = a1 * a2 / (a1 + a2); // 7.46867e-4 m
	for (const double factor : { 1.0, 2.0 }) {
		p.leverFactor       = factor;
		const ContactArms c = contactArms(p, g, 1e-5);
		EXPECT_NEAR(c.arm1, a1, 1e-18);
		EXPECT_NEAR(c.arm2, a2, 1e-18);
		EXPECT_NEAR(c.lever, factor * reduced, 1e-18);
	}
	g.radius2 = 0;
	EXPECT_NEAR(contactArms(p, g, 1e-5).lever, 2 * a1, 1e-18);
	// The contact point's velocity takes each sphere's spin with its own arm:
	// w1 x (a1 n) + w2 x (a2 n) with n = z, w1 = (0, 2, 0), w2 = (1, 0, 0), arms 1 and 3: (2, -3, 0).
	const Vec3 vc = sphereContactVelocity(Vec3(0, 0, 1), Vec3(Vec3::Zero()), Vec3(0, 2, 0), Vec3(1, 0, 0), 1, 3);
	EXPECT_NEAR((vc - Vec3(2, -3, 0)).norm(), 0, 1e-15);
}

TEST(Kinematics, RollingAndTorsionOpposeRelativeRotation)
{
	const Vec3              n(0, 0, 1);
	const Vec3              vc = sphereContactVelocity(n, Vec3(Vec3::Zero()), Vec3(0, 2, 3), Vec3(Vec3::Zero()), 1, 1);
	const ContactVelocities c  = contactVelocities(n, vc, Vec3(0, 2, 3), 0.5);
	EXPECT_NEAR((vc - Vec3(2, 0, 0)).norm(), 0, 1e-15); // w x (arm n) = (0, 2, 3) x (0, 0, 1)
	EXPECT_NEAR(c.rolling.x(), -1.0, 1e-15);            // 0.5 n x (0, 2, 3) = (-1, 0, 0)
	EXPECT_NEAR(c.torsion, 1.5, 1e-15);
}

TEST(Energy, ElasticCycleDissipatesNothingSlipDissipatesFriction)
{
	PairParams p;
	p.sliding = element(100, 0, 1.0, 1.0);
	setMechanisms(p, false);
	TangentialState   s;
	Vec3              fT = Vec3::Zero();
	const Vec3        n(0, 0, 1);
	ContactVelocities v { Vec3(1e-3, 0, 0), Vec3::Zero(), 0.0 };
	double            diss = 0;
	TangentialEnergy  e;
	const double      dt = 1e-3;
	for (int i = 0; i < 100; ++i) {
		tangentialStep(p, s, fT, v, n, 0, dt, 10.0, &e);
		diss += e.sliding;
	}
	v.sliding = -v.sliding;
	for (int i = 0; i < 100; ++i) {
		tangentialStep(p, s, fT, v, n, 0, dt, 10.0, &e);
		diss += e.sliding;
	}
	EXPECT_NEAR(diss, 0, 1e-15);
	EXPECT_NEAR(s.xiT.norm(), 0, 1e-15);
	// Now slip: level 0.001 -> limit 1e-3 N; pushing 0.1 m further at the limit dissipates ~1e-4 J.
	v.sliding = Vec3(1e-3, 0, 0);
	diss      = 0;
	for (int i = 0; i < 100000; ++i) {
		tangentialStep(p, s, fT, v, n, 0, dt, 1e-3, &e);
		diss += e.sliding;
	}
	const double slip = 0.1 - 1e-3 / 100; // total displacement minus the elastic part
	EXPECT_NEAR(diss, 1e-3 * slip, 1e-12);
}
