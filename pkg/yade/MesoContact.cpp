#include "MesoContact.hpp"
#include <core/BodyContainer.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <pkg/common/Sphere.hpp>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((MesoMat)(MesoPhys)(Ip2_MesoMat_MesoMat_MesoPhys)(Law2_ScGeom_MesoPhys_Meso));

/* MesoMat */

namespace {
	// The numeric attributes of MesoMat and the core parameters they are (frictionAngle and the
	// mode names are converted, below).
	struct Field {
		Real MesoMat::*attr;
		double meso::MaterialParams::*param;
	};
	const Field numericFields[] = { { &MesoMat::k1, &meso::MaterialParams::k1 },         { &MesoMat::kp, &meso::MaterialParams::kp },
		                        { &MesoMat::kc, &meso::MaterialParams::kc },         { &MesoMat::phiF, &meso::MaterialParams::phiF },
		                        { &MesoMat::fa, &meso::MaterialParams::fa },         { &MesoMat::kca, &meso::MaterialParams::kca },
		                        { &MesoMat::gammaN, &meso::MaterialParams::gammaN }, { &MesoMat::phiD, &meso::MaterialParams::phiD },
		                        { &MesoMat::kt, &meso::MaterialParams::kt },         { &MesoMat::gammaT, &meso::MaterialParams::gammaT },
		                        { &MesoMat::kr, &meso::MaterialParams::kr },         { &MesoMat::gammaR, &meso::MaterialParams::gammaR },
		                        { &MesoMat::muR, &meso::MaterialParams::muR },       { &MesoMat::ko, &meso::MaterialParams::ko },
		                        { &MesoMat::gammaO, &meso::MaterialParams::gammaO }, { &MesoMat::muO, &meso::MaterialParams::muO } };
}

meso::MaterialParams MesoMat::parse() const
{
	meso::MaterialParams m;
	for (const Field& f : numericFields)
		m.*f.param = this->*f.attr;
	m.adhesion        = meso::parseAdhesion(adhesion);
	m.k2Interpolation = meso::parseK2Interpolation(k2Interpolation);
	if (!(frictionAngle >= 0 && frictionAngle < 0.5 * M_PI))
		throw std::invalid_argument("frictionAngle = " + std::to_string(frictionAngle) + " is invalid: must lie in [0, pi/2)");
	m.muS      = math::tan(frictionAngle);
	m.dominant = dominant;
	return m;
}

void MesoMat::postLoad(MesoMat&)
{
	if (deferChecks) return;
	try {
		meso::MaterialParams m = parse();
		meso::validate(m);
		valid                = m;
		validAdhesion        = adhesion;
		validK2Interpolation = k2Interpolation;
	} catch (const std::invalid_argument&) { // keep the material valid: undo the assignment, then report it
		for (const Field& f : numericFields)
			this->*f.attr = valid.*f.param;
		frictionAngle   = math::atan(valid.muS);
		dominant        = valid.dominant;
		adhesion        = validAdhesion;
		k2Interpolation = validK2Interpolation;
		throw;
	}
}

void MesoMat::setFrictionAngle(Real a)
{
	frictionAngle = a;
	postLoad(*this);
}

void MesoMat::pyHandleCustomCtorArgs(boost::python::tuple&, boost::python::dict& kw)
{
	// Apply all keywords first and check once, so that kp >= k1 or fa with kca can be given in any order.
	deferChecks = true;
	try {
		pyUpdateAttrs(kw);
	} catch (...) {
		deferChecks = false;
		throw;
	}
	deferChecks = false;
	kw.clear();
	postLoad(*this);
}

/* Ip2 */

void Ip2_MesoMat_MesoMat_MesoPhys::postLoad(Ip2_MesoMat_MesoMat_MesoPhys&)
{
	if (leverArm == "reduced") leverFactor = 1;
	else if (leverArm == "a12") leverFactor = 2;
	else {
		const std::string bad = leverArm;
		leverArm              = leverFactor == 2 ? "a12" : "reduced";
		throw std::invalid_argument("leverArm = '" + bad + "' is invalid: must be 'reduced' or 'a12'");
	}
}

namespace {
	Real sphereRadius(const Body::id_t id, Scene* scene) // 0 for walls, boxes, facets
	{
		const auto* sphere = dynamic_cast<const Sphere*>(Body::byId(id, scene)->shape.get());
		return sphere ? sphere->radius : 0;
	}
}

void Ip2_MesoMat_MesoMat_MesoPhys::go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I)
{
	if (I->phys) return;
	const auto* mat1 = static_cast<const MesoMat*>(m1.get());
	const auto* mat2 = static_cast<const MesoMat*>(m2.get());
	const Real  r1   = sphereRadius(I->getId1(), scene);
	const Real  r2   = sphereRadius(I->getId2(), scene);
	// Against a wall, box or facet a12 is the limit 2 a of the formula (MODEL.md §1); the radii
	// those geometries report are not used, they differ between YADE's Ig2 functors.
	const Real a12 = (r1 > 0 && r2 > 0) ? 2 * r1 * r2 / (r1 + r2) : 2 * (r1 > 0 ? r1 : r2);

	auto phys                    = shared_ptr<MesoPhys>(new MesoPhys());
	meso::PairParams& p          = phys->pair;
	p                            = meso::mixPair(mat1->params(), mat2->params(), a12);
	p.radius1                    = r1;
	p.radius2                    = r2;
	p.leverFactor                = leverFactor;
	p.tangential                 = p.sliding.active() || p.rolling.active() || p.twisting.active();
	p.rollTwist                  = (p.rolling.active() || p.twisting.active()) && dynamic_cast<const ScGeom6D*>(I->geom.get());
	phys->history.k2             = p.k1;
	phys->kn                     = p.kp;
	phys->ks                     = p.sliding.k;
	phys->tangensOfFrictionAngle = p.sliding.muS;
	I->phys                      = phys;
}

/* Law2 */

bool Law2_ScGeom_MesoPhys_Meso::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	const auto*  geom  = static_cast<const ScGeom*>(ig.get());
	auto*        phys  = static_cast<MesoPhys*>(ip.get());
	const auto&  p     = phys->pair;
	const Real   delta = geom->penetrationDepth;
	const int    id1 = I->getId1(), id2 = I->getId2();
	const auto&     bodies = scene->bodies->body; // the vector itself: its operator[] inlines
	const State*    s1     = bodies[id1]->state.get();
	const State*    s2     = bodies[id2]->state.get();
	const Vector3r&      n      = geom->normal; // from 1 to 2
	Vector3r        relVel = s1->vel - s2->vel;
	if (scene->isPeriodic) relVel -= scene->cell->intrShiftVel(I->cellDist);
	const Real vn = relVel.dot(n); // d(delta)/dt

	const meso::NormalForce f = meso::normalForce(p, phys->history, delta, vn);
	if (scene->trackEnergy) {
		if (std::isnan(phys->energy.prevDelta)) phys->energy.prevDelta = delta - vn * scene->dt; // no force before
		const meso::NormalEnergyStep e = meso::energyStep(phys->energy, phys->history, phys->force, f, delta);
		scene->energy->add(e.elastic, "mesoElastic", elasticIx, /*reset*/ true);
		scene->energy->add(e.plastic, "mesoPlastic", plasticIx, false);
		scene->energy->add(e.adhesive, "mesoAdhesive", adhesiveIx, false);
		scene->energy->add(e.viscous, "mesoViscous", viscousIx, false);
	}
	phys->force       = f;
	phys->normalForce = f.total() * n;
	Vector3r force1   = -phys->normalForce; // on body 1

	if (p.tangential) {
		const Real dt   = scene->dt;
		auto&      t    = phys->tangential;
		const bool both = p.radius1 > 0 && p.radius2 > 0;
		// Arms from the centres to the contact point: a - delta/2 for spheres (branch = +-arm n);
		// for a wall, box or facet the branch to YADE's contact point.
		const Real arm1 = p.radius1 > 0 ? p.radius1 - 0.5 * delta : 0;
		const Real arm2 = p.radius2 > 0 ? p.radius2 - 0.5 * delta : 0;
		const Real lever = p.leverFactor * (both ? arm1 * arm2 / (arm1 + arm2) : math::max(arm1, arm2));
		phys->lastLever  = lever;
		Vector3r b1, b2; // used off the sphere-sphere path only
		Vector3r vc;
		if (both) vc = meso::sphereContactVelocity(n, relVel, s1->angVel, s2->angVel, arm1, arm2);
		else {
			const Vector3r shift2 = scene->isPeriodic ? scene->cell->intrShiftPos(I->cellDist) : Vector3r::Zero();
			b1                    = p.radius1 > 0 ? Vector3r(arm1 * n) : Vector3r(geom->contactPoint - s1->pos);
			b2                    = p.radius2 > 0 ? Vector3r(-arm2 * n) : Vector3r(geom->contactPoint - s2->pos - shift2);
			vc                    = relVel + meso::cross(s1->angVel, b1) - meso::cross(s2->angVel, b2);
		}
		const meso::ContactVelocities v = meso::contactVelocities(n, vc, s1->angVel - s2->angVel, lever);
		meso::TangentialEnergy  e;
		meso::TangentialEnergy* ePtr = scene->trackEnergy ? &e : nullptr;
		if (delta > 0) {
			// The frame spins with the pair's mean spin about n; against a wall, with the wall's.
			const Real spin  = both ? 0.5 * (s1->angVel + s2->angVel).dot(n) : (p.radius1 > 0 ? s2->angVel : s1->angVel).dot(n);
			const Real level = f.hysteretic + f.viscous + p.kc * delta;
			meso::tangentialStep(p, p.rollTwist, t, v, n, spin * dt, dt, level, ePtr);
		} else if (t.nPrev.squaredNorm() > 0) {
			meso::tangentialRelease(p, t, v, dt, ePtr);
		}
		if (ePtr) {
			scene->energy->add(e.stored, "mesoSprings", springsIx, true);
			scene->energy->add(e.sliding, "mesoSliding", slidingIx, false);
			scene->energy->add(e.rolling, "mesoRolling", rollingIx, false);
			scene->energy->add(e.twisting, "mesoTwisting", twistingIx, false);
		}
		phys->shearForce = -t.fT; // YADE's convention: the force sustained by body 2
		if (delta > 0) {
			force1 += t.fT;
			const Vector3r quasiTorque = lever * (t.fO * n - meso::cross(n, t.fR)); // rolling and torsion, on body 1
			if (both) {
				const Vector3r nxf = meso::cross(n, t.fT); // sliding: torques arm1 n x fT and arm2 n x fT
				scene->forces.addTorque(id1, arm1 * nxf + quasiTorque);
				scene->forces.addTorque(id2, arm2 * nxf - quasiTorque);
			} else {
				scene->forces.addTorque(id1, meso::cross(b1, t.fT) + quasiTorque);
				scene->forces.addTorque(id2, meso::cross(t.fT, b2) - quasiTorque);
			}
		}
	}
	if (force1 != Vector3r::Zero()) {
		scene->forces.addForce(id1, force1);
		scene->forces.addForce(id2, -force1);
	}
	return meso::keepsInteracting(p, delta);
}

} // namespace yade
