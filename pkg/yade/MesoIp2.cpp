// Ip2_MesoMat_MesoMat_MesoPhys: mixes two materials into the pair's parameters (shared by the
// pair's contacts), makes each contact's MesoPhys, and checks the step, the depth and the detection.
#include "MesoContact.hpp"
#include "PyChecks.hpp"
#include <core/BodyContainer.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <iostream>
#include <pkg/common/Sphere.hpp>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((Ip2_MesoMat_MesoMat_MesoPhys));

/* Ip2 */

void Ip2_MesoMat_MesoMat_MesoPhys::postLoad(Ip2_MesoMat_MesoMat_MesoPhys&)
{
	{ // new contacts take the new lever arm
		const std::lock_guard<std::mutex> lock(sharedMutex);
		sharedParams.clear();
	}
	if (leverArm == "reduced") leverFactor = 1;
	else if (leverArm == "a12")
		leverFactor = 2;
	else {
		const std::string bad = leverArm;
		leverArm              = leverFactor == 2 ? "a12" : "reduced";
		throw std::invalid_argument("leverArm = '" + bad + "' is invalid: must be 'reduced' or 'a12'");
	}
}

void Ip2_MesoMat_MesoMat_MesoPhys::pyHandleCustomCtorArgs(boost::python::tuple&, boost::python::dict& kw)
{
	static const pychecks::Field fields[] = { { "leverArm", pychecks::Kind::Text } };
	pychecks::checkKeywords(kw, fields);
	pychecks::ctorKeywords(*this, kw, { "stableDt" });
}

namespace {
	Real sphereRadius(const Body::id_t id, Scene* scene) // 0 for walls, boxes, facets
	{
		const auto* sphere = dynamic_cast<const Sphere*>(Body::byId(id, scene)->shape.get());
		return sphere ? sphere->radius : 0;
	}
	const MesoMat& asMeso(const shared_ptr<Material>& m, const char* name) // the Python entry points' check
	{
		const auto* mat = dynamic_cast<const MesoMat*>(m.get());
		if (!mat) throw std::invalid_argument(std::string(name) + " must be a MesoMat, not " + (m ? m->getClassName() : std::string("None")));
		return *mat;
	}
}

meso::PairParams Ip2_MesoMat_MesoMat_MesoPhys::mix(const MesoMat& m1, const MesoMat& m2, bool rotations) const
{
	meso::PairParams p = meso::mixPair(m1.params(), m2.params());
	p.leverFactor      = leverFactor;
	meso::setMechanisms(p, rotations);
	return p;
}

shared_ptr<MesoPairParams> Ip2_MesoMat_MesoMat_MesoPhys::pairParams(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, bool geom6D)
{
	const auto*                       mat1 = static_cast<const MesoMat*>(m1.get());
	const auto*                       mat2 = static_cast<const MesoMat*>(m2.get());
	const std::lock_guard<std::mutex> lock(sharedMutex);
	Shared&                           s = sharedParams[std::make_tuple(mat1, mat2, geom6D)];
	if (s.params && s.revision1 == mat1->revision() && s.revision2 == mat2->revision()) return s.params;
	s.m1             = m1;
	s.m2             = m2;
	s.revision1      = mat1->revision();
	s.revision2      = mat2->revision();
	s.params         = shared_ptr<MesoPairParams>(new MesoPairParams());
	s.params->params = mix(*mat1, *mat2, geom6D);
	return s.params;
}

boost::python::dict
Ip2_MesoMat_MesoMat_MesoPhys::mixedParameters(const boost::python::object& m1, const boost::python::object& m2, const boost::python::object& rotations) const
{
	const meso::PairParams p
	        = mix(asMeso(pychecks::instance<Material>("material1", m1, "a MesoMat"), "material1"),
	              asMeso(pychecks::instance<Material>("material2", m2, "a MesoMat"), "material2"),
	              pychecks::flag("rotations", rotations));
	boost::python::dict d;
#define MESO_ENTRY(name, ...) d[#name] = p.name;
	MESO_NORMAL_PARAMS(MESO_ENTRY)
	MESO_ADDED_PARAMS(MESO_ENTRY)
#undef MESO_ENTRY
	d["phiD"]            = p.phiD;
	d["deltaA"]          = p.deltaA;
	d["adhesion"]        = std::string(meso::adhesionName(p.adhesion));
	d["k2Interpolation"] = std::string(meso::k2InterpolationName(p.k2Interpolation));
	const struct {
		const char*                name;
		const meso::ElementParams& e;
		bool                       acts;
	} elements[] = { { "sliding", p.sliding, p.slidingActs }, { "rolling", p.rolling, p.rollingActs }, { "torsion", p.torsion, p.torsionActs } };
	for (const auto& el : elements) {
		boost::python::dict e;
		e["k"]     = el.e.k;
		e["gamma"] = el.e.gamma;
		e["muS"]   = el.e.muS;
		e["muD"]   = el.e.muD;
		e["acts"]  = el.acts;
		d[el.name] = e;
	}
	d["leverFactor"] = p.leverFactor;
	return d;
}

Real Ip2_MesoMat_MesoMat_MesoPhys::stableStepFor(
        const boost::python::object& m1,
        const boost::python::object& m2,
        const boost::python::object& r1,
        const boost::python::object& r2,
        const boost::python::object& rot) const
{
	const Real radius1 = pychecks::number("radius1", r1), radius2 = pychecks::number("radius2", r2);
	const bool rotations = pychecks::flag("rotations", rot);
	if (!(radius1 > 0) || !std::isfinite(radius1))
		throw std::invalid_argument("radius1 = " + pychecks::digits(radius1) + " is invalid: must be a finite number > 0 [m]");
	if (!(radius2 >= 0) || !std::isfinite(radius2))
		throw std::invalid_argument("radius2 = " + pychecks::digits(radius2) + " is invalid: must be a finite number >= 0 [m] (0: a fixed wall)");
	const MesoMat&         a        = asMeso(pychecks::instance<Material>("material1", m1, "a MesoMat"), "material1");
	const MesoMat&         b        = asMeso(pychecks::instance<Material>("material2", m2, "a MesoMat"), "material2");
	const meso::PairParams p        = mix(a, b, rotations);
	auto                   inverses = [](const MesoMat& m, Real r, Real& invMass, Real& invInertia) { // a free sphere; 0: fixed
                invMass = invInertia = 0;
                if (r <= 0) return;
                const Real mass = 4.0 / 3.0 * M_PI * r * r * r * m.density;
                invMass         = 1 / mass;
                invInertia      = 1 / (0.4 * mass * r * r);
	};
	Real invM1, invI1, invM2, invI2;
	inverses(a, radius1, invM1, invI1);
	inverses(b, radius2, invM2, invI2);
	const char* which = "";
	return meso::stableStep(p, meso::pairGeometry(p, radius1, radius2), invM1, invM2, invI1, invI2, &which);
}

void Ip2_MesoMat_MesoMat_MesoPhys::adoptMaterials(const boost::python::object& interaction)
{
	const shared_ptr<Interaction> I    = pychecks::instance<Interaction>("interaction", interaction, "an Interaction (O.interactions[i, j])");
	auto*                         phys = I ? dynamic_cast<MesoPhys*>(I->phys.get()) : nullptr;
	if (!phys || !I->geom || !phys->pairParams) throw std::invalid_argument("interaction: must be a real interaction with MesoPhys made by this Ip2");
	Scene*                  sc = Omega::instance().getScene().get();
	const shared_ptr<Body>& b1 = Body::byId(I->getId1(), sc);
	const shared_ptr<Body>& b2 = Body::byId(I->getId2(), sc);
	if (!b1 || !b2 || !dynamic_cast<MesoMat*>(b1->material.get()) || !dynamic_cast<MesoMat*>(b2->material.get()))
		throw std::invalid_argument("interaction: both bodies must exist and carry a MesoMat");
	shared_ptr<MesoPairParams> params = pairParams(b1->material, b2->material, dynamic_cast<const ScGeom6D*>(I->geom.get()) != nullptr);
	const meso::PairParams&    now    = params->params;
	const meso::PairParams&    old    = phys->pairParams->params;
	for (const auto& [name, a, b] :
	     { std::make_tuple("k1", now.k1, old.k1), std::make_tuple("kp", now.kp, old.kp), std::make_tuple("phiF", now.phiF, old.phiF) })
		if (a != b)
			throw std::invalid_argument(
			        std::string("interaction: the new materials change the pair's ") + name + ", which shapes the contact history");
	if (now.k2Interpolation != old.k2Interpolation) throw std::invalid_argument("interaction: the new materials change the pair's k2Interpolation");
	if (now.tangential != (dynamic_cast<MesoTangentialPhys*>(phys) != nullptr))
		throw std::invalid_argument("interaction: the new materials switch the tangential mechanisms on or off (the contact class cannot change)");
	phys->pairParams             = params;
	phys->ks                     = now.sliding.k;
	phys->tangensOfFrictionAngle = now.sliding.muS;
}

void Ip2_MesoMat_MesoMat_MesoPhys::go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I)
{
	if (I->phys) return;
	shared_ptr<MesoPairParams> params = pairParams(m1, m2, dynamic_cast<const ScGeom6D*>(I->geom.get()) != nullptr);
	const meso::PairParams&    p      = params->params;
	// Law2::go() relies on it: a pair with tangential mechanisms gets the class that holds the springs.
	auto phys        = p.tangential ? shared_ptr<MesoPhys>(new MesoTangentialPhys()) : shared_ptr<MesoPhys>(new MesoPhys());
	phys->pairParams = params;
	// Against a wall, box or facet a12 is the limit 2 a of the formula (docs/model.md §1); the radii
	// those geometries report are not used, they differ between YADE's Ig2 functors.
	phys->geometry               = meso::pairGeometry(p, sphereRadius(I->getId1(), scene), sphereRadius(I->getId2(), scene));
	phys->kn                     = p.kp;
	phys->ks                     = p.sliding.k;
	phys->tangensOfFrictionAngle = p.sliding.muS;
	I->phys                      = phys;
	checkTimeStep(*phys, *I);
	checkDepth(*I);
	if (meso::actsAcrossGap(p.adhesion)) checkDetection(*phys, *I);
}

void Ip2_MesoMat_MesoMat_MesoPhys::checkDepth(const Interaction& I)
{
	// A contact born deeper than a radius starts with elastic energy nobody put in: the law (and its
	// energy account) assumes contacts that grow from touching. Said once, not refused: a user may mean it.
	const auto* geom = dynamic_cast<const ScGeom*>(I.geom.get());
	if (!geom) return;
	const Real r1 = sphereRadius(I.getId1(), scene), r2 = sphereRadius(I.getId2(), scene);
	const Real r = r1 > 0 && r2 > 0 ? std::min(r1, r2) : std::max(r1, r2); // walls report 0
	if (!(r > 0 && geom->penetrationDepth > r) || depthWarned.exchange(true)) return;
	std::cerr << "WARNING Ip2_MesoMat_MesoMat_MesoPhys: contact #" << I.getId1() << "+#" << I.getId2() << " was made with overlap "
	          << geom->penetrationDepth << " m, deeper than the radius " << r
	          << " m: the law assumes contacts that grow from touching, so its start holds elastic energy that no work put in "
	          << "(O.energy does not close) and the repulsion throws the bodies apart. Start from a packing without such overlaps "
	          << "(grow the radii or let the spheres settle with a softer law first). (Warned once.)" << std::endl;
}

void Ip2_MesoMat_MesoMat_MesoPhys::checkDetection(const MesoPhys& phys, const Interaction& I)
{
	// The pull-in of a mode that acts across the gap (reversible): a pair made already in contact, which was
	// inside the range a step ago, missed it (one that crossed the whole range in a step lost nothing,
	// nor did a pair that overlapped before the first step).
	const auto* geom = dynamic_cast<const ScGeom*>(I.geom.get());
	if (!geom || !(geom->penetrationDepth > 0) || scene->iter == 0) return;
	const Body& b1     = *Body::byId(I.getId1(), scene);
	const Body& b2     = *Body::byId(I.getId2(), scene);
	Vector3r    relVel = b1.state->vel - b2.state->vel;
	if (scene->isPeriodic) relVel -= scene->cell->intrShiftVel(I.cellDist);
	const Real before = geom->penetrationDepth - relVel.dot(geom->normal) * scene->dt; // the overlap a step ago
	if (!(before > phys.pair().deltaA) || rangeWarned.exchange(true)) return;
	// What should have seen the pair: the geometry functor of its shapes.
	const std::string s1 = b1.shape ? b1.shape->getClassName() : "?", s2 = b2.shape ? b2.shape->getClassName() : "?";
	const std::string other = s1 == "Sphere" ? s2 : s1;
	std::string       what;
	if (other == "Facet" || other == "Wall")
		what = "YADE's Ig2_" + other + "_Sphere_ScGeom makes contacts only in overlap: use Ig2_" + other
		        + "_Sphere_MesoScGeom (yade-meso; for facets also ...6D) with interactionDetectionFactor";
	else
		what = "Ig2_" + other + "_Sphere_ScGeom.interactionDetectionFactor";
	std::cerr << "WARNING Ip2_MesoMat_MesoMat_MesoPhys: the " << s1 << "-" << s2 << " contact #" << I.getId1() << "+#" << I.getId2() << " with '"
	          << meso::adhesionName(phys.pair().adhesion) << "' non-contact adhesion was made already in contact (overlap " << geom->penetrationDepth
	          << " m), so its pull-in over the range " << -phys.pair().deltaA << " m was missed. Detect pairs at that gap: " << what
	          << " and Bo1_Sphere_Aabb.aabbEnlargeFactor >= 1 + range/radius; mesocontact.scene.set_detection() sets them "
	          << "(call it after the engines and bodies are in place, and again after adding smaller spheres or a larger range). "
	          << "(Warned once.)" << std::endl;
}

void Ip2_MesoMat_MesoMat_MesoPhys::checkTimeStep(const MesoPhys& phys, const Interaction& I)
{
	auto inverses = [this](Body::id_t id, Real& invMass, Real& invInertia) {
		const Body& b = *Body::byId(id, scene);
		invMass = invInertia = 0;
		if (!b.isDynamic()) return; // moved by the user or an engine: not integrated
		if (b.state->mass > 0) invMass = 1 / b.state->mass;
		const Real i = b.state->inertia.minCoeff();
		if (i > 0) invInertia = 1 / i;
	};
	Real invM1, invI1, invM2, invI2;
	inverses(I.getId1(), invM1, invI1);
	inverses(I.getId2(), invM2, invI2);
	const char* which = "";
	const Real  dt    = meso::stableStep(phys.pair(), phys.geometry, invM1, invM2, invI1, invI2, &which);
	{
		const std::lock_guard<std::mutex> lock(sharedMutex);
		if (dt < stableDt) stableDt = dt;
	}
	if (scene->dt > dt && !dtWarned.exchange(true))
		std::cerr << "WARNING Ip2_MesoMat_MesoMat_MesoPhys: O.dt = " << scene->dt << " s exceeds the stable step " << dt << " s of contact #"
		          << I.getId1() << "+#" << I.getId2() << " (its " << which << " element): the integration is unstable. (Warned once; "
		          << "the smallest stable step so far is the functor's stableDt.)" << std::endl;
}

} // namespace yade
