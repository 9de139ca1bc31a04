// A store of contacts kept aside while yade.mpy erases and remakes pairs (its split, its collision
// steps) or moves bodies to another worker (its reallocation), given back to the same pairs with
// their history. Each store owns what it keeps; mesocontact.mpi holds one per process.
#pragma once
#include "PyChecks.hpp"
#include <core/Body.hpp>
#include <core/IGeom.hpp>
#include <core/IPhys.hpp>
#include <lib/serialization/Serializable.hpp>
#include <vector>

namespace yade {

class Scene;

class MesoContactStore : public Serializable {
	struct Kept {
		Body::id_t        id1, id2;
		shared_ptr<IGeom> geom;
		shared_ptr<IPhys> phys;
	};
	std::vector<Kept>      kept;                                    // Python calls the methods one at a time (GIL held)
	boost::weak_ptr<Scene> from;                                    // contacts of another scene (even at the same address) are never given back
	void                   keepFor(const shared_ptr<Scene>& scene); // forgets what was kept from another scene

public:
	// In C++ rather than Python: an object assigned from Python carries a Python reference that the
	// engine thread would later drop without the GIL.
	long keep();
	long restore();
	long size() const { return static_cast<long>(kept.size()); }
	// The same contacts as bytes for another rank (those of the given bodies), and kept from them.
	boost::python::object exportContacts(const boost::python::object& ids) const;
	long                  importContacts(const boost::python::object& data);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(MesoContactStore,Serializable,"Contacts (geometry and physics of real interactions, any law) kept aside by body ids and given back to the same pairs with their history: across an operation that erases and remakes pairs, such as :yref:`yade.mpy`'s split and collision steps, and from one process to another (``mesocontact.mpi`` uses one store per process). What a store keeps is never given to another scene (e.g. after ``O.load``), and is not saved with it.",
		/*attrs*/,
		/*ctor*/,
		.def("keep",&MesoContactStore::keep,"Keeps the geometry and physics of every real interaction of the scene, forgetting what was kept before; returns how many.")
		.def("restore",&MesoContactStore::restore,"Gives the kept geometry and physics back to every pair that exists again without them (both bodies present, the collider's candidate interaction made), with the bodies in the order the contact was made for, so it goes on with its history; pairs still real keep their own. Forgets the kept contacts and returns how many it gave back (none if the scene is not the one they were kept from). ``ValueError`` (and nothing given back, the contacts still kept) if a kept geometry is not of the class this scene's :yref:`InteractionLoop` makes for its pair (contacts from a scene with other Ig2 functors: YADE's functors would cast it to the wrong type).")
		.def("exportContacts",&MesoContactStore::exportContacts,(boost::python::arg("ids")),"The real interactions of the scene that involve any of the bodies ``ids`` (a sequence or set of ids), serialized as ``O.save`` does, as bytes: for another process (``mesocontact.mpi`` sends them with the bodies that :yref:`yade.mpy` moves to another worker). Keeps nothing.")
		.def("importContacts",&MesoContactStore::importContacts,(boost::python::arg("data")),"Adds the contacts of ``data`` (bytes from :yref:`exportContacts<MesoContactStore.exportContacts>`) to the kept ones, which :yref:`restore<MesoContactStore.restore>` gives to their pairs; call it after :yref:`keep<MesoContactStore.keep>`, which forgets what was kept before. Returns how many; ``ValueError`` if ``data`` is not such bytes (bytes appended to an export included).")
		.add_property("size",&MesoContactStore::size,"How many contacts are kept now.");
		pychecks::guard(_classObj)
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(MesoContactStore);

} // namespace yade
