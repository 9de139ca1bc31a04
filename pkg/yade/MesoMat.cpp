// MesoMat (a material's parameters, every change validated on a copy before it is made) and the
// per-contact classes MesoPairParams, MesoPhys, MesoTangentialPhys.
#include "MesoContact.hpp"
#include "PyChecks.hpp"
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((MesoMat)(MesoPairParams)(MesoPhys)(MesoTangentialPhys));

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

	// A Python property whose every assignment is tried on a copy of the material first: a refused
	// value (ValueError naming the parameter) leaves the material as it was.
	template <class T> void checkedOnCopy(boost::python::object& cls, const char* name, T MesoMat::*attr)
	{
		namespace bp = boost::python;
		auto get     = [attr](const MesoMat& m) { return m.*attr; };
		auto set     = [name, attr](MesoMat& m, const bp::object& v) {
                        const T value = pychecks::convert<T>(name, v);
                        m.change([&](MesoMat& c) { c.*attr = value; });
		};
		pychecks::replaceProperty(
		        cls,
		        name,
		        bp::make_function(get, bp::default_call_policies(), boost::mpl::vector<T, const MesoMat&>()),
		        bp::make_function(set, bp::default_call_policies(), boost::mpl::vector<void, MesoMat&, const bp::object&>()));
	}
}

void MesoMat::registerChecked(boost::python::object& cls)
{
	for (const Field& f : numericFields)
		checkedOnCopy(cls, f.name, f.attr);
	checkedOnCopy(cls, "adhesion", &MesoMat::adhesion);
	checkedOnCopy(cls, "k2Interpolation", &MesoMat::k2Interpolation);
	checkedOnCopy(cls, "dominant", &MesoMat::dominant);
	pychecks::checked(cls, "frictionAngle", &MesoMat::getFrictionAngle, &MesoMat::setFrictionAngle);
	pychecks::checked(cls, "density", &MesoMat::getDensity, &MesoMat::setDensity);
	pychecks::checked(cls, "young", &MesoMat::getYoung, &MesoMat::setYoung);
	pychecks::checked(cls, "poisson", &MesoMat::getPoisson, &MesoMat::setPoisson);
	// inherited attributes, only typed: a wrong type names them instead of Boost's "None.None(...)"
	pychecks::checked(cls, "label", &MesoMat::getLabel, &MesoMat::setLabel);
	pychecks::checked(cls, "id", &MesoMat::getId, &MesoMat::setId);
}

meso::MaterialParams MesoMat::parse() const
{
	meso::MaterialParams m;
	for (const Field& f : numericFields)
		m.*f.param = this->*f.attr;
	m.adhesion        = meso::parseAdhesion(adhesion);
	m.k2Interpolation = meso::parseK2Interpolation(k2Interpolation);
	if (!(frictionAngle >= 0 && frictionAngle < 0.5 * M_PI))
		throw std::invalid_argument("frictionAngle = " + pychecks::digits(frictionAngle) + " is invalid: must lie in [0, pi/2)");
	m.muS = math::tan(frictionAngle);
	if (m.muS != 0 && !(m.muS >= meso::kSmallestValue && m.muS <= meso::kLargestValue)) // named here, not as the core's muS
		throw std::invalid_argument(
		        "frictionAngle = " + pychecks::digits(frictionAngle) + " is invalid: its tangent (the sliding coefficient) " + pychecks::digits(m.muS)
		        + " lies outside [1e-100, 1e100] (0 allowed)");
	m.dominant = dominant;
	// Not parameters of the law, but a mass of 0, < 0 or NaN (density) or a wrong time step (young,
	// read by PWaveTimeStep) would make any run meaningless without a word.
	if (!(std::isfinite(density) && density >= meso::kSmallestValue && density <= meso::kLargestValue))
		throw std::invalid_argument(
		        "density = " + pychecks::digits(density)
		        + " is invalid: must be a finite number in [1e-100, 1e100] [kg/m^3] (masses and 1/m stay within floating point)");
	if (!(std::isfinite(young) && young >= meso::kSmallestValue && young <= meso::kLargestValue))
		throw std::invalid_argument(
		        "young = " + pychecks::digits(young)
		        + " is invalid: must be a finite number in [1e-100, 1e100] [Pa] (not used by the law; PWaveTimeStep reads it)");
	// YADE's FrictMat laws take it as the ratio ks/kn: a MesoMat-FrictMat contact with NaN there moves bodies to NaN.
	if (!(std::isfinite(poisson) && poisson >= 0 && poisson <= 1))
		throw std::invalid_argument(
		        "poisson = " + pychecks::digits(poisson)
		        + " is invalid: must be a finite number in [0, 1] (not used by the law; YADE's FrictMat laws read it as ks/kn)");
	return m;
}

void MesoMat::postLoad(MesoMat&)
{
	if (deferChecks) return;
	meso::MaterialParams m = parse(); // a refused value throws; change() tries it on a copy first
	meso::validate(m);
	valid = m;
	++revisionCount;
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
	// All keywords at once, then one check, so that kp >= k1 or fa with kca can be given in any order.
	change([&d](MesoMat& c) {
		c.deferChecks = true;
		try {
			c.pyUpdateAttrs(d);
		} catch (...) {
			c.deferChecks = false;
			throw;
		}
		c.deferChecks = false;
	});
}

void MesoMat::setFrictionAngle(Real a)
{
	change([a](MesoMat& c) { c.frictionAngle = a; });
}

void MesoMat::setDensity(Real d)
{
	change([d](MesoMat& c) { c.density = d; });
}

void MesoMat::setYoung(Real y)
{
	change([y](MesoMat& c) { c.young = y; });
}

void MesoMat::setPoisson(Real p)
{
	change([p](MesoMat& c) { c.poisson = p; });
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

boost::python::tuple MesoMat::adhesionModes()
{
	boost::python::list out;
	for (const meso::AdhesionMode& m : meso::kAdhesionModes)
		out.append(std::string(m.name));
	return boost::python::tuple(out);
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
	if (geometry.meshFacet < -1) refuse("meshFacet", geometry.meshFacet, "must be a body id or -1");
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

int                  MesoPhys::byteSize() const { return dynamic_cast<const MesoTangentialPhys*>(this) ? sizeof(MesoTangentialPhys) : sizeof(MesoPhys); }
boost::python::tuple MesoPhys::branchNames()
{
	boost::python::list out;
	for (const char* name : meso::kBranchNames)
		out.append(std::string(name));
	return boost::python::tuple(out);
}

} // namespace yade
