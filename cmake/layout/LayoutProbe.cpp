// Build-time layout check (cmake/layout/check_layout.py): the plugin is compiled against headers
// fetched from Debian's YADE source package, which may be of another version than the installed
// library. This Python module, compiled with the plugin's headers and flags, reads the members the
// plugin touches from objects the installed library made and filled; check_layout.py compares
// them with what the library itself reports. A member at another offset reads another value.
#include <core/Body.hpp>
#include <core/BodyContainer.hpp>
#include <core/Cell.hpp>
#include <core/EnergyTracker.hpp>
#include <core/ForceContainer.hpp>
#include <core/Functor.hpp>
#include <core/GlobalEngine.hpp>
#include <core/Interaction.hpp>
#include <core/InteractionContainer.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <core/Dispatching.hpp>
#include <pkg/common/ElastMat.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/common/Wall.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

#include <boost/preprocessor/seq/for_each.hpp>
#include <boost/preprocessor/stringize.hpp>
#include <boost/python.hpp>
#include <malloc.h>

namespace py = boost::python;
using namespace yade;

namespace {
py::tuple vec(const Vector3r& v) { return py::make_tuple(double(v[0]), double(v[1]), double(v[2])); }
py::tuple vec(const Vector3i& v) { return py::make_tuple(v[0], v[1], v[2]); }
py::tuple mat(const Matrix3r& m)
{
	py::list rows;
	for (int i = 0; i < 3; ++i)
		rows.append(py::make_tuple(double(m(i, 0)), double(m(i, 1)), double(m(i, 2))));
	return py::tuple(rows);
}
template <class T> T& object(py::object o) { return py::extract<T&>(o)(); }

// sizeof of each class as these headers lay it out, and the usable size of the block the library
// allocated for an object (glibc rounds sizeof + 8 up to 16 bytes, minus 8).
py::dict sizes()
{
	py::dict d;
	d["Serializable"]  = sizeof(Serializable);
	d["Material"]      = sizeof(Material);
	d["ElastMat"]      = sizeof(ElastMat);
	d["FrictMat"]      = sizeof(FrictMat);
	d["IPhys"]         = sizeof(IPhys);
	d["NormPhys"]      = sizeof(NormPhys);
	d["NormShearPhys"] = sizeof(NormShearPhys);
	d["FrictPhys"]     = sizeof(FrictPhys);
	d["IGeom"]         = sizeof(IGeom);
	d["ScGeom"]        = sizeof(ScGeom);
	d["ScGeom6D"]      = sizeof(ScGeom6D);
	d["State"]         = sizeof(State);
	d["Body"]          = sizeof(Body);
	d["Interaction"]   = sizeof(Interaction);
	d["Sphere"]        = sizeof(Sphere);
	d["Facet"]         = sizeof(Facet);
	d["Wall"]          = sizeof(Wall);
	d["IGeomFunctor"]  = sizeof(IGeomFunctor);
	d["IPhysFunctor"]  = sizeof(IPhysFunctor);
	d["LawFunctor"]    = sizeof(LawFunctor);
	d["GlobalEngine"]  = sizeof(GlobalEngine);
	return d;
}
size_t usable(py::object o) { return malloc_usable_size(py::extract<Serializable*>(o)()); }

// One reading per member: d["name"] = the member as Python sees it (pointers as addresses).
py::object                    value(Real x) { return py::object(double(x)); }
py::object                    value(int x) { return py::object(x); }
py::object                    value(bool x) { return py::object(x); }
py::object                    value(const Vector3r& v) { return vec(v); }
py::object                    value(const Vector3i& v) { return vec(v); }
template <class T> py::object value(const shared_ptr<T>& p) { return py::object(size_t(p.get())); }
py::object                    value(const std::vector<Vector3r>& v)
{
	py::list l;
	for (const auto& x : v)
		l.append(vec(x));
	return py::tuple(l);
}
// A reader of class T: the listed members as Python sees them, by name (pointers as addresses).
#define READ_MEMBER(r, obj, member) d[BOOST_PP_STRINGIZE(member)] = value(obj.member);
#define READER(fname, T, members)                                                                                                                              \
	py::dict fname(py::object o)                                                                                                                           \
	{                                                                                                                                                      \
		const T& x = object<T>(o);                                                                                                                     \
		py::dict d;                                                                                                                                    \
		BOOST_PP_SEQ_FOR_EACH(READ_MEMBER, x, members)                                                                                                 \
		return d;                                                                                                                                      \
	}
READER(state, State, (pos)(vel)(angVel)(mass)(inertia))
READER(material, FrictMat, (density)(young)(frictionAngle)(id))
READER(sphere, Sphere, (radius))
READER(facet, Facet, (vertices))
READER(wall, Wall, (axis)(sense))
READER(phys, FrictPhys, (kn)(ks)(normalForce)(shearForce)(tangensOfFrictionAngle))
READER(geom, ScGeom, (penetrationDepth)(normal)(contactPoint))
READER(bodyMembers, Body, (id)(clumpId)(state)(shape)(material))
READER(interactionMembers, Interaction, (cellDist)(geom)(phys))
py::dict body(py::object o) // and what the plugin calls on it
{
	py::dict d         = bodyMembers(o);
	d["isDynamic"]     = object<Body>(o).isDynamic();
	d["isClumpMember"] = object<Body>(o).isClumpMember();
	return d;
}
py::dict interaction(py::object o)
{
	const Interaction& i = object<Interaction>(o);
	py::dict           d = interactionMembers(o);
	d["id1"]             = i.getId1();
	d["id2"]             = i.getId2();
	d["isReal"]          = i.isReal();
	return d;
}
size_t address(py::object o) { return size_t(py::extract<Serializable*>(o)()); }
// The functor's scene pointer, which the library's dispatchers set before calling it.
size_t functorScene(py::object o) { return size_t(object<Functor>(o).scene); }
size_t engineScene(py::object o) { return size_t(object<Engine>(o).scene); }

// The present scene: scalars first; the pointers only after check_layout.py found those right.
py::dict scene()
{
	const Scene& s = *Omega::instance().getScene();
	py::dict     d;
	d["address"]     = size_t(&s);
	d["dt"]          = double(s.dt);
	d["iter"]        = s.iter;
	d["isPeriodic"]  = s.isPeriodic;
	d["trackEnergy"] = s.trackEnergy;
	return d;
}
py::dict sceneContainers()
{
	Scene&   s = *Omega::instance().getScene();
	py::dict d;
	d["bodies"]       = s.bodies->size();
	d["interactions"] = s.interactions->size();
	s.forces.sync(); // the library's functions, on the container at these headers' offset
	d["force0"]      = vec(s.forces.getForce(0));
	d["energyNames"] = s.energy->names.size();
	if (s.isPeriodic) {
		d["hSize"]           = mat(s.cell->hSize);
		d["velGrad"]         = mat(s.cell->velGrad);
		d["prevHSize"]       = mat(s.cell->prevHSize);
		d["intrShiftPos100"] = vec(s.cell->intrShiftPos(Vector3i(1, 0, 0)));
		d["intrShiftVel100"] = vec(s.cell->intrShiftVel(Vector3i(1, 0, 0)));
	}
	return d;
}
} // namespace

BOOST_PYTHON_MODULE(meso_layout_probe)
{
	py::def("sizes", sizes);
	py::def("usable", usable);
	py::def("address", address);
	py::def("state", state);
	py::def("body", body);
	py::def("material", material);
	py::def("sphere", sphere);
	py::def("facet", facet);
	py::def("wall", wall);
	py::def("phys", phys);
	py::def("geom", geom);
	py::def("interaction", interaction);
	py::def("functorScene", functorScene);
	py::def("engineScene", engineScene);
	py::def("scene", scene);
	py::def("sceneContainers", sceneContainers);
}
