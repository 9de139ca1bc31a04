#include "MesoContact.hpp"
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((MesoMat)(MesoPhys)(Ip2_MesoMat_MesoMat_MesoPhys)(Law2_ScGeom_MesoPhys_Meso));

/* MesoMat */

meso::MaterialParams MesoMat::params() const
{
	meso::MaterialParams m;
	m.k1              = k1;
	m.kp              = kp;
	m.kc              = kc;
	m.phiF            = phiF;
	m.fa              = fa;
	m.kca             = kca;
	m.gammaN          = gammaN;
	m.adhesion        = meso::parseAdhesion(adhesion);
	m.k2Interpolation = meso::parseK2Interpolation(k2Interpolation);
	return m;
}

void MesoMat::postLoad(MesoMat&)
{
	if (deferChecks) return;
	try {
		meso::MaterialParams m = params();
		meso::validate(m);
		lastValid           = m;
		lastAdhesion        = adhesion;
		lastK2Interpolation = k2Interpolation;
	} catch (const std::invalid_argument&) { // keep the material valid: undo the assignment, then report it
		k1              = lastValid.k1;
		kp              = lastValid.kp;
		kc              = lastValid.kc;
		phiF            = lastValid.phiF;
		fa              = lastValid.fa;
		kca             = lastValid.kca;
		gammaN          = lastValid.gammaN;
		adhesion        = lastAdhesion;
		k2Interpolation = lastK2Interpolation;
		throw;
	}
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

void Ip2_MesoMat_MesoMat_MesoPhys::go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I)
{
	if (I->phys) return;
	const auto* mat1 = static_cast<const MesoMat*>(m1.get());
	const auto* mat2 = static_cast<const MesoMat*>(m2.get());
	const auto* geom = YADE_CAST<GenericSpheresContact*>(I->geom.get());
	const Real  r1   = geom->refR1 > 0 ? geom->refR1 : geom->refR2;
	const Real  r2   = geom->refR2 > 0 ? geom->refR2 : geom->refR1;
	const Real  a12  = 2 * r1 * r2 / (r1 + r2);

	auto phys                    = shared_ptr<MesoPhys>(new MesoPhys());
	phys->pair                   = meso::mixPair(mat1->params(), mat2->params(), a12);
	phys->history.k2             = phys->pair.k1;
	phys->kn                     = phys->pair.kp;
	phys->ks                     = 0;
	phys->tangensOfFrictionAngle = math::tan(math::min(mat1->frictionAngle, mat2->frictionAngle));
	I->phys                      = phys;
}

/* Law2 */

bool Law2_ScGeom_MesoPhys_Meso::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	const auto*  geom  = static_cast<const ScGeom*>(ig.get());
	auto*        phys  = static_cast<MesoPhys*>(ip.get());
	const Real   delta = geom->penetrationDepth;
	const int    id1 = I->getId1(), id2 = I->getId2();
	const State* s1 = Body::byId(id1, scene)->state.get();
	const State* s2 = Body::byId(id2, scene)->state.get();
	Vector3r     relVel = s1->vel - s2->vel;
	if (scene->isPeriodic) relVel -= scene->cell->intrShiftVel(I->cellDist);
	const Real vn = relVel.dot(geom->normal); // d(delta)/dt: the normal points from 1 to 2

	const meso::NormalForce f = meso::normalForce(phys->pair, phys->history, delta, vn);
	if (scene->trackEnergy) {
		if (std::isnan(phys->energy.prevDelta)) phys->energy.prevDelta = delta - vn * scene->dt; // no force before
		const meso::NormalEnergyStep e = meso::energyStep(phys->energy, phys->history, phys->force, f, delta);
		scene->energy->add(e.elastic, "mesoElastic", elasticIx, /*reset*/ true);
		scene->energy->add(e.plastic, "mesoPlastic", plasticIx, false);
		scene->energy->add(e.adhesive, "mesoAdhesive", adhesiveIx, false);
		scene->energy->add(e.viscous, "mesoViscous", viscousIx, false);
	}
	phys->force             = f;
	const Real ft           = f.total();
	phys->normalForce       = ft * geom->normal;
	if (ft != 0) {
		scene->forces.addForce(id1, -phys->normalForce);
		scene->forces.addForce(id2, phys->normalForce);
	}
	return meso::keepsInteracting(phys->pair, delta);
}

} // namespace yade
