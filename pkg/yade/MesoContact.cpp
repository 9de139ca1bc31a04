#include "MesoContact.hpp"
#include "PyChecks.hpp"
#include "PyRelease.hpp"
#include <core/BodyContainer.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <iostream>
#include <core/State.hpp>
#include <pkg/common/Sphere.hpp>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((MesoMat)(MesoPairParams)(MesoPhys)(MesoTangentialPhys)(Ip2_MesoMat_MesoMat_MesoPhys)(Law2_ScGeom_MesoPhys_Meso));

/* MesoMat */

namespace {
	// The numeric attributes of MesoMat and the core parameters they are (frictionAngle and the
	// mode names are converted, below).
	struct Field {
		const char* name;
		Real MesoMat::*attr;
		double meso::MaterialParams::*param;
	};
#define MESO_FIELD(name, ...) { #name, &MesoMat::name, &meso::MaterialParams::name },
	const Field numericFields[] = { MESO_ALL_PARAMS(MESO_FIELD) };
#undef MESO_FIELD
	using pychecks::Kind;
	// The other attributes a MesoMat validates (numericFields are numbers too).
	const pychecks::Field otherKeywords[]
	        = { { "density", Kind::Number }, { "young", Kind::Number },         { "frictionAngle", Kind::Number },
		    { "adhesion", Kind::Text },  { "k2Interpolation", Kind::Text }, { "dominant", Kind::Flag },
		    { "poisson", Kind::Number }, { "label", Kind::Text },           { "id", Kind::Integer } }; // the last three inherited, unchecked values
	void checkMesoMatKeywords(boost::python::dict& kw) // numbers handed on as Python floats (numpy's too)
	{
		for (const Field& f : numericFields)
			if (kw.has_key(f.name)) kw[f.name] = pychecks::number(f.name, kw[f.name]);
		pychecks::checkKeywords(kw, otherKeywords);
	}
}

void MesoMat::registerChecked(boost::python::object& cls)
{
	for (const Field& f : numericFields)
		pychecks::checked(cls, f.name, f.attr);
	pychecks::checked(cls, "adhesion", &MesoMat::adhesion);
	pychecks::checked(cls, "k2Interpolation", &MesoMat::k2Interpolation);
	pychecks::checked(cls, "dominant", &MesoMat::dominant);
	pychecks::checked(cls, "frictionAngle", &MesoMat::getFrictionAngle, &MesoMat::setFrictionAngle);
	pychecks::checked(cls, "density", &MesoMat::getDensity, &MesoMat::setDensity);
	pychecks::checked(cls, "young", &MesoMat::getYoung, &MesoMat::setYoung);
}

namespace {
	std::string number(Real v) // all digits: a rejected 1e-20 must not read "0.000000"
	{
		std::ostringstream out;
		out.precision(17);
		out << v;
		return out.str();
	}
}

meso::MaterialParams MesoMat::parse() const
{
	meso::MaterialParams m;
	for (const Field& f : numericFields)
		m.*f.param = this->*f.attr;
	m.adhesion        = meso::parseAdhesion(adhesion);
	m.k2Interpolation = meso::parseK2Interpolation(k2Interpolation);
	if (!(frictionAngle >= 0 && frictionAngle < 0.5 * M_PI))
		throw std::invalid_argument("frictionAngle = " + number(frictionAngle) + " is invalid: must lie in [0, pi/2)");
	m.muS = math::tan(frictionAngle);
	if (m.muS != 0 && !(m.muS >= meso::kSmallestValue && m.muS <= meso::kLargestValue)) // named here, not as the core's muS
		throw std::invalid_argument(
		        "frictionAngle = " + number(frictionAngle) + " is invalid: its tangent (the sliding coefficient) " + number(m.muS)
		        + " lies outside [1e-100, 1e100] (0 allowed)");
	m.dominant = dominant;
	// Not parameters of the law, but a mass of 0, < 0 or NaN (density) or a wrong time step (young,
	// read by PWaveTimeStep) would make any run meaningless without a word.
	if (!(std::isfinite(density) && density >= meso::kSmallestValue && density <= meso::kLargestValue))
		throw std::invalid_argument(
		        "density = " + number(density)
		        + " is invalid: must be a finite number in [1e-100, 1e100] [kg/m^3] (masses and 1/m stay within floating point)");
	if (!(std::isfinite(young) && young > 0))
		throw std::invalid_argument("young = " + number(young) + " is invalid: must be a finite number > 0 [Pa] (not used by the law)");
	return m;
}

void MesoMat::postLoad(MesoMat&)
{
	if (deferChecks) return;
	try {
		meso::MaterialParams m = parse();
		meso::validate(m);
		valid = m;
		++revisionCount;
		validAdhesion        = adhesion;
		validK2Interpolation = k2Interpolation;
		validFrictionAngle   = frictionAngle;
		validDensity         = density;
		validYoung           = young;
	} catch (const std::invalid_argument&) { // keep the material valid: undo every assignment (updateAttrs makes several), then report
		undoToValid();
		throw;
	}
}

void MesoMat::undoToValid()
{
	for (const Field& f : numericFields)
		this->*f.attr = valid.*f.param;
	frictionAngle   = validFrictionAngle; // not atan(muS): that can differ by an ulp
	density         = validDensity;
	young           = validYoung;
	dominant        = valid.dominant;
	adhesion        = validAdhesion;
	k2Interpolation = validK2Interpolation;
}

void MesoMat::updateAttrsChecked(const boost::python::dict& given)
{
	boost::python::dict d = boost::python::dict(given).copy(); // the caller's dict stays as it was
	checkMesoMatKeywords(d);                                   // every type, before any value is set
	const boost::python::object cls  = boost::python::import("yade.wrapper").attr("MesoMat");
	const boost::python::list   keys = d.keys();
	for (long i = 0; i < boost::python::len(keys); ++i) {
		const boost::python::object key = keys[i];
		if (!PyUnicode_Check(key.ptr()) || !PyObject_HasAttr(cls.ptr(), key.ptr())) {
			const std::string name = boost::python::extract<std::string>(boost::python::str(key));
			PyErr_SetString(PyExc_AttributeError, ("updateAttrs: MesoMat has no attribute '" + name + "'; nothing was set").c_str());
			boost::python::throw_error_already_set();
		}
	}
	// The inherited attributes are not part of what postLoad validates and undoes: kept here.
	const Real        poissonBefore = poisson;
	const std::string labelBefore   = label;
	const int         idBefore      = id;
	try {
		pyUpdateAttrs(d); // ends with postLoad, which undoes all of them if a value is refused
	} catch (...) {           // anything YADE's own setters refuse half-way: undo what was set before it
		undoToValid();
		poisson = poissonBefore;
		label   = labelBefore;
		id      = idBefore;
		throw;
	}
}

void MesoMat::setFrictionAngle(Real a)
{
	frictionAngle = a;
	postLoad(*this);
}

void MesoMat::setDensity(Real d)
{
	density = d;
	postLoad(*this);
}

void MesoMat::setYoung(Real y)
{
	young = y;
	postLoad(*this);
}

void MesoMat::pyHandleCustomCtorArgs(boost::python::tuple&, boost::python::dict& kw)
{
	checkMesoMatKeywords(kw); // a wrong type named before any is applied
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

/* MesoPhys */

const meso::TangentialState& MesoPhys::tangentialState() const
{
	static const meso::TangentialState none;
	const auto*                        t = dynamic_cast<const MesoTangentialPhys*>(this);
	return t ? t->tangential : none;
}

void MesoPairParams::postLoad(MesoPairParams&)
{
	try {
		meso::validatePair(params);
	} catch (const std::invalid_argument& e) {
		throw std::runtime_error(std::string("MesoPairParams (a saved contact's pair parameters): ") + e.what());
	}
}

void MesoPhys::postLoad(MesoPhys&)
{
	if (!pairParams) return; // made from Python: the law remakes it (Law2_ScGeom_MesoPhys_Meso::dropForeign)
	// A contact's state as read from a file (an edited or damaged one must not run on with NaN).
	auto refuse = [this](const char* name, Real v, const char* rule) {
		std::ostringstream out;
		out.precision(17);
		out << getClassName() << " (a saved contact): " << name << " = " << v << " is invalid: " << rule;
		throw std::runtime_error(out.str());
	};
	for (const auto& [name, v] : { std::make_pair("deltaMax", Real(history.deltaMax)),
	                               std::make_pair("delta0", Real(history.delta0)),
	                               std::make_pair("fHysteretic", fHysteretic),
	                               std::make_pair("fViscous", fViscous) })
		if (!std::isfinite(v)) refuse(name, v, "must be finite");
	if (std::isinf(lastDelta)) refuse("lastDelta", lastDelta, "must be finite (NaN before the first step)");
	if (!(std::isfinite(geometry.radius1) && geometry.radius1 >= 0)) refuse("radius1", geometry.radius1, "must be finite and >= 0");
	if (!(std::isfinite(geometry.radius2) && geometry.radius2 >= 0 && geometry.radius1 + geometry.radius2 > 0))
		refuse("radius2", geometry.radius2, "must be finite and >= 0, one radius > 0");
	if (!(std::isfinite(geometry.invDeltaMaxP) && geometry.invDeltaMaxP >= 0)) refuse("invDeltaMaxP", geometry.invDeltaMaxP, "must be finite and >= 0");
	const bool springs = dynamic_cast<const MesoTangentialPhys*>(this) != nullptr;
	if (pairParams->params.tangential != springs)
		throw std::runtime_error(
		        getClassName() + ": its pair parameters " + (springs ? "have no" : "have") + " sliding, rolling or torsion, which a "
		        + (springs ? "MesoTangentialPhys does not fit" : "plain MesoPhys cannot hold (it has no springs)")
		        + "; the saved contact was not made by Ip2_MesoMat_MesoMat_MesoPhys.");
}

boost::python::dict MesoPhys::stateDict() const
{
	boost::python::dict d = pyDict(); // what YADE lists: FrictPhys's attributes
	d["deltaMax"]         = getDeltaMax();
	d["delta0"]           = getDelta0();
	d["k2"]               = getK2();
	d["deltaMaxP"]        = getDeltaMaxP();
	d["delta0P"]          = getDelta0P();
	d["deltaA"]           = getDeltaA();
	d["a12"]              = getA12();
	d["touched"]          = getTouched();
	d["branch"]           = getBranch();
	d["hystereticForce"]  = getFh();
	d["adhesiveForce"]    = getFadh();
	d["viscousForce"]     = getFv();
	d["coulombLevel"]     = getCoulombLevel();
	d["adhesion"]         = getAdhesion();
	d["k2Interpolation"]  = getK2Interpolation();
#define MESO_DICT_ENTRY(name, def, unit, ok, rule, mix, dest, ...) d[#name] = pair().dest;
	MESO_ALL_PARAMS(MESO_DICT_ENTRY)
#undef MESO_DICT_ENTRY
	if (pair().tangential) {
		d["slidingSpring"] = getXiT();
		d["rollingSpring"] = getXiR();
		d["torsionSpring"] = getXiO();
		d["rollingForce"]  = getFR();
		d["torsionForce"]  = getFO();
		d["leverArm"]      = getLeverArm();
	}
	return d;
}

int MesoPhys::byteSize() const { return dynamic_cast<const MesoTangentialPhys*>(this) ? sizeof(MesoTangentialPhys) : sizeof(MesoPhys); }

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
		throw std::invalid_argument("radius1 = " + number(radius1) + " is invalid: must be a finite number > 0 [m]");
	if (!(radius2 >= 0) || !std::isfinite(radius2))
		throw std::invalid_argument("radius2 = " + number(radius2) + " is invalid: must be a finite number >= 0 [m] (0: a fixed wall)");
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

boost::python::tuple MesoMat::adhesionModes()
{
	boost::python::list out;
	for (const meso::AdhesionMode& m : meso::kAdhesionModes)
		out.append(std::string(m.name));
	return boost::python::tuple(out);
}

boost::python::tuple MesoPhys::branchNames()
{
	boost::python::list out;
	for (const char* name : meso::kBranchNames)
		out.append(std::string(name));
	return boost::python::tuple(out);
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
	MESO_HOT PairMotion pairMotion(const Scene* scene, const ScGeom& geom, const Interaction* I)
	{
		const auto& bodies = scene->bodies->body; // the vector itself: its operator[] inlines
		PairMotion  m { bodies[I->getId1()]->state.get(), bodies[I->getId2()]->state.get(), Vector3r::Zero(), 0 };
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
	const PairMotion m     = pairMotion(scene, geom, I);
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
