// Law2_ScGeom_MesoPhys_Meso: each step, the YADE-free core (pkg/core) on one contact, and its
// forces, torques and energies applied to the scene.
#include "MesoContact.hpp"
#include "PyRelease.hpp"
#include <core/BodyContainer.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <iostream>

namespace yade {

YADE_PLUGIN((Law2_ScGeom_MesoPhys_Meso));

/* Law2 */

void Law2_ScGeom_MesoPhys_Meso::registerEnergies(bool tangential)
{
	const std::lock_guard<std::mutex> lock(energyMutex);
	if (!normalEnergiesReady.load(std::memory_order_relaxed)) {
		addEnergies(meso::NormalEnergyStep {});
		normalEnergiesReady.store(true, std::memory_order_release);
	}
	if (tangential && !tangentialEnergiesReady.load(std::memory_order_relaxed)) {
		addEnergies(meso::TangentialEnergy {});
		tangentialEnergiesReady.store(true, std::memory_order_release);
	}
}

// The one place each energy's name is written (the first call registers it; stored energies are
// reset every step, dissipated ones accumulate).
void Law2_ScGeom_MesoPhys_Meso::addEnergies(const meso::NormalEnergyStep& e)
{
	scene->energy->add(e.elastic, "mesoElastic", elasticIx, /*reset*/ true);
	scene->energy->add(e.plastic, "mesoPlastic", plasticIx, false);
	scene->energy->add(e.adhesive, "mesoAdhesive", adhesiveIx, false);
	scene->energy->add(e.viscous, "mesoViscous", viscousIx, false);
}

void Law2_ScGeom_MesoPhys_Meso::addEnergies(const meso::TangentialEnergy& e)
{
	scene->energy->add(e.stored, "mesoSprings", springsIx, /*reset*/ true);
	scene->energy->add(e.sliding, "mesoSliding", slidingIx, false);
	scene->energy->add(e.rolling, "mesoRolling", rollingIx, false);
	scene->energy->add(e.torsion, "mesoTorsion", torsionIx, false);
}

using pyrelease::heldByPython;
using pyrelease::releaseInPython;

bool Law2_ScGeom_MesoPhys_Meso::adopt(shared_ptr<IPhys>& ip, Interaction* I)
{
	auto* phys = static_cast<MesoPhys*>(ip.get());
	if (!phys->pairParams) return dropForeign(ip, I);
	if (phys->owner && heldByPython(ip)) { // another contact's phys: two contacts must not share one history
		if (!borrowedWarned.exchange(true))
			std::cerr << "WARNING Law2_ScGeom_MesoPhys_Meso: contact #" << I->getId1() << "+#" << I->getId2() << " was given the "
			          << ip->getClassName() << " of another contact (assigned from Python): it is dropped and remade from the bodies' "
			          << "materials at the next step, so that each contact keeps its own history. (Warned once.)" << std::endl;
		releaseInPython(ip);
		return true;
	}
	phys->owner = I; // loaded, restored, or made by the Ip2 for this interaction
	return false;
}

bool Law2_ScGeom_MesoPhys_Meso::dropForeign(shared_ptr<IPhys>& ip, const Interaction* I)
{
	// No exception can leave YADE's OpenMP loop, so the phys is dropped: the Ip2 makes a proper one
	// at the next step (from the bodies' materials, history afresh), and the user is told.
	if (!foreignWarned.exchange(true))
		std::cerr << "WARNING Law2_ScGeom_MesoPhys_Meso: contact #" << I->getId1() << "+#" << I->getId2() << " has a " << ip->getClassName()
		          << " not made by Ip2_MesoMat_MesoMat_MesoPhys (e.g. assigned from Python): it is "
		          << "dropped and remade from the bodies' materials at the next step. To change a live contact's materials, "
		          << "use Ip2_MesoMat_MesoMat_MesoPhys.adoptMaterials. (Warned once.)" << std::endl;
	releaseInPython(ip);
	return true;
}

// The kinematics of the tangential elements: the arms, the relative velocities at the contact
// point, the spin of the contact frame about n, and the branches from the centres to that point.
struct MesoKinematics {
	meso::ContactArms       arms;
	meso::ContactVelocities v;
	Real                    spin;   // the frame spins with the pair's mean spin about n; against a wall, with the wall's
	Vector3r                b1, b2; // branches, set for a wall, box or facet only (spheres use arm n)
};

namespace {
	// The two bodies of a contact and how they move relative to each other at its centre.
	struct PairMotion {
		const State* s1;
		const State* s2;
		Vector3r     relVel; // v1 - v2, the periodic cell's shift included
		Real         vn;     // d(delta)/dt, > 0 while approaching
	};
	// meshFacet: a facet contact that travelled onto another facet of its mesh moves with that facet.
	MESO_HOT PairMotion pairMotion(const Scene* scene, const ScGeom& geom, const Interaction* I, int meshFacet)
	{
		const auto& bodies = scene->bodies->body; // the vector itself: its operator[] inlines
		Body::id_t  id1    = I->getId1();
		if (meshFacet >= 0 && size_t(meshFacet) < bodies.size() && bodies[meshFacet]) [[unlikely]]
			id1 = meshFacet;
		PairMotion m { bodies[id1]->state.get(), bodies[I->getId2()]->state.get(), Vector3r::Zero(), 0 };
		m.relVel = m.s1->vel - m.s2->vel;
		if (scene->isPeriodic) m.relVel -= scene->cell->intrShiftVel(I->cellDist);
		m.vn = meso::dot(m.relVel, geom.normal);
		return m;
	}

	// Two spheres: the branches are +-arm n.
	MESO_HOT MesoKinematics
	sphereSphereKinematics(const meso::PairParams& p, const meso::PairGeometry& g, const ScGeom& geom, const PairMotion& m, Real delta)
	{
		MesoKinematics  k;
		const Vector3r& n = geom.normal;
		k.arms            = meso::contactArms(p, g, delta);
		const Vector3r vc = meso::sphereContactVelocity(n, m.relVel, m.s1->angVel, m.s2->angVel, k.arms.arm1, k.arms.arm2);
		k.v               = meso::contactVelocities(n, vc, m.s1->angVel - m.s2->angVel, k.arms.lever);
		k.spin            = 0.5 * meso::dot(m.s1->angVel + m.s2->angVel, n);
		return k;
	}
	// A sphere and a wall, box or facet: the branch of the wall to YADE's contact point.
	MESO_HOT MesoKinematics sphereWallKinematics(
	        const Scene*              scene,
	        const meso::PairParams&   p,
	        const meso::PairGeometry& g,
	        const ScGeom&             geom,
	        const PairMotion&         m,
	        const Interaction*        I,
	        Real                      delta)
	{
		MesoKinematics  k;
		const Vector3r& n     = geom.normal;
		k.arms                = meso::contactArms(p, g, delta);
		const Vector3r shift2 = scene->isPeriodic ? scene->cell->intrShiftPos(I->cellDist) : Vector3r::Zero();
		k.b1                  = g.radius1 > 0 ? Vector3r(k.arms.arm1 * n) : Vector3r(geom.contactPoint - m.s1->pos);
		k.b2                  = g.radius2 > 0 ? Vector3r(-k.arms.arm2 * n) : Vector3r(geom.contactPoint - m.s2->pos - shift2);
		const Vector3r vc     = m.relVel + meso::cross(m.s1->angVel, k.b1) - meso::cross(m.s2->angVel, k.b2);
		k.v                   = meso::contactVelocities(n, vc, m.s1->angVel - m.s2->angVel, k.arms.lever);
		k.spin                = meso::dot(g.radius1 > 0 ? m.s2->angVel : m.s1->angVel, n);
		return k;
	}

	// Force fT at the contact point (sliding) and the quasi-torques of rolling and torsion, on body 1;
	// their opposites on body 2.
	MESO_HOT void addTangentialTorques(
	        Scene* scene, int id1, int id2, bool spheres, const MesoKinematics& k, const Vector3r& n, const Vector3r& fT, const meso::TangentialState& t)
	{
		const Vector3r quasiTorque = k.arms.lever * (t.fO * n - meso::cross(n, t.fR));
		if (spheres) {
			const Vector3r nxf = meso::cross(n, fT); // sliding: torques arm1 n x fT and arm2 n x fT
			scene->forces.addTorque(id1, k.arms.arm1 * nxf + quasiTorque);
			scene->forces.addTorque(id2, k.arms.arm2 * nxf - quasiTorque);
		} else {
			scene->forces.addTorque(id1, meso::cross(k.b1, fT) + quasiTorque);
			scene->forces.addTorque(id2, meso::cross(fT, k.b2) - quasiTorque);
		}
	}
}

MESO_HOT meso::NormalForce Law2_ScGeom_MesoPhys_Meso::normalStep(MesoPhys& phys, const meso::PairParams& p, Real delta, Real vn)
{
	meso::NormalForce f;
	if (scene->trackEnergy) {
		if (!normalEnergiesReady.load(std::memory_order_acquire)) registerEnergies(p.tangential);
		meso::NormalEnergyStep e;
		f = meso::normalStepWithEnergy(p, phys.geometry, phys.history, { phys.fHysteretic, phys.fViscous, phys.lastDelta }, delta, vn, scene->dt, e);
		addEnergies(e);
	} else {
		f = meso::normalForce(p, phys.geometry, phys.history, delta, vn);
	}
	phys.fHysteretic = f.hysteretic;
	phys.fViscous    = f.viscous;
	phys.lastDelta   = delta;
	return f;
}

MESO_HOT void Law2_ScGeom_MesoPhys_Meso::tangentialStep(
        MesoTangentialPhys& phys, const meso::PairParams& p, const MesoKinematics& k, const Vector3r& n, Real delta, Real level, Vector3r& fT)
{
	const Real dt = scene->dt;
	auto&      t  = phys.tangential;
	// Without energy tracking no energy record is made or added (callgrind: fewer instructions).
	auto advance = [&](meso::TangentialEnergy * e) __attribute__((always_inline))
	{
		if (delta > 0) meso::tangentialStep(p, t, fT, k.v, n, k.spin * dt, dt, level, e);
		else if (meso::dot(t.nPrev, t.nPrev) > 0)
			meso::tangentialRelease(p, t, fT, k.v, dt, e);
	};
	if (scene->trackEnergy) {
		if (!tangentialEnergiesReady.load(std::memory_order_acquire)) registerEnergies(true);
		meso::TangentialEnergy e;
		advance(&e);
		addEnergies(e);
	} else {
		advance(nullptr);
	}
}

bool Law2_ScGeom_MesoPhys_Meso::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	const auto& geom  = *static_cast<const ScGeom*>(ig.get());
	const int   index = ip->getClassIndex(); // the dispatcher's cached choice outlives a phys replaced from Python
	if (index != MesoPhys::getClassIndexStatic() && index != MesoTangentialPhys::getClassIndexStatic()) [[unlikely]]
		return dropForeign(ip, I);
	if (static_cast<MesoPhys*>(ip.get())->owner != I) [[unlikely]]
		if (adopt(ip, I)) return true;
	auto* const      phys  = static_cast<MesoPhys*>(ip.get());
	const auto&      p     = phys->pairParams->params;
	const Real       delta = geom.penetrationDepth;
	const Vector3r&  n     = geom.normal; // from 1 to 2
	const PairMotion m     = pairMotion(scene, geom, I, phys->geometry.meshFacet);
	if (neighbourSums) neighbourSums->add(*I, geom, *m.s1, *m.s2, phys->geometry.radius1 > 0, phys->geometry.radius2 > 0, scene);
	const meso::NormalForce f = normalStep(*phys, p, delta, m.vn);
	phys->normalForce         = f.total() * n;
	Vector3r force1           = -phys->normalForce; // on body 1
	if (p.tangential) {
		const auto&          g       = phys->geometry;
		const bool           spheres = g.radius1 > 0 && g.radius2 > 0;
		const MesoKinematics k       = spheres ? sphereSphereKinematics(p, g, geom, m, delta) : sphereWallKinematics(scene, p, g, geom, m, I, delta);
		auto&                tphys   = *static_cast<MesoTangentialPhys*>(phys); // the Ip2 made it so
		Vector3r             fT      = -phys->shearForce;                       // YADE keeps the force sustained by body 2
		tangentialStep(tphys, p, k, n, delta, meso::coulombLevel(p, f.hysteretic, f.viscous, delta), fT);
		phys->shearForce = -fT;
		if (delta > 0) {
			force1 += fT;
			addTangentialTorques(scene, I->getId1(), I->getId2(), spheres, k, n, fT, tphys.tangential);
		}
	}
	if (force1 != Vector3r::Zero()) {
		scene->forces.addForce(I->getId1(), force1);
		scene->forces.addForce(I->getId2(), -force1);
	}
	if (meso::keepsInteracting(p, delta)) [[likely]]
		return true;
	pyrelease::releaseIfHeld(ip); // the contact ends: YADE would release them in this thread
	pyrelease::releaseIfHeld(ig);
	return false;
}

} // namespace yade
