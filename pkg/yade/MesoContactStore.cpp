// The contact store (MesoContactStore.hpp): kept by body ids, given back to pairs made anew, sent
// as bytes of the scene's own archive. Any law's contacts are kept, not only this one's.
#include "MesoContactStore.hpp"
#include "MesoContact.hpp"
#include <core/BodyContainer.hpp>
#include <core/InteractionContainer.hpp>
#include <core/InteractionLoop.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <lib/serialization/ObjectIO.hpp>
#include <cstdint>
#include <cstdio>
#include <boost/serialization/shared_ptr.hpp>
#include <boost/serialization/vector.hpp>
#include <boost/python/stl_iterator.hpp>
#include <map>
#include <set>
#include <sstream>

namespace yade {

YADE_PLUGIN((MesoContactStore));

namespace {
	// Marks the bytes as ours, so that other bytes are refused before boost reads lengths from them.
	// Version 2 carries a checksum of the archive: Boost's binary archive trusts its input, and a
	// damaged export could crash it (a forged one still can: import only what exportContacts made).
	const std::string contactsTag = "mesocontact contacts 2\n";
	const std::size_t sumDigits   = 16;

	std::string checksum(const std::string& bytes, std::size_t from) // FNV-1a, 64 bits, as hex digits
	{
		std::uint64_t h = 14695981039346656037ull;
		for (std::size_t k = from; k < bytes.size(); ++k) {
			h ^= static_cast<unsigned char>(bytes[k]);
			h *= 1099511628211ull;
		}
		char digits[sumDigits + 1];
		std::snprintf(digits, sizeof(digits), "%016llx", static_cast<unsigned long long>(h));
		return std::string(digits, sumDigits);
	}
}

void MesoContactStore::keepFor(const shared_ptr<Scene>& scene)
{
	if (from.lock() != scene) kept.clear();
	from = scene;
}

long MesoContactStore::keep()
{
	const shared_ptr<Scene>& scene = Omega::instance().getScene();
	kept.clear();
	from = scene;
	for (const auto& I : *scene->interactions)
		if (I->isReal()) kept.push_back({ I->getId1(), I->getId2(), I->geom, I->phys });
	return static_cast<long>(kept.size());
}

namespace {
	// The geometry functors of the scene's interaction loop (null without one).
	IGeomDispatcher* geometryOf(const Scene& sc)
	{
		for (const auto& e : sc.engines)
			if (const auto* loop = dynamic_cast<const InteractionLoop*>(e.get())) return loop->geomDispatcher.get();
		return nullptr;
	}
	// The meso Ip2 functor of the scene's interaction loop (null without one).
	Ip2_MesoMat_MesoMat_MesoPhys* mesoPhysOf(const Scene& sc)
	{
		for (const auto& e : sc.engines)
			if (const auto* loop = dynamic_cast<const InteractionLoop*>(e.get()))
				for (const auto& f : loop->physDispatcher->functors)
					if (auto* ip2 = dynamic_cast<Ip2_MesoMat_MesoMat_MesoPhys*>(f.get())) return ip2;
		return nullptr;
	}
	// The class of geometry the scene's loop makes for this pair, made once on a scratch interaction
	// (a restored geometry of another class would be cast to the wrong type by the functor).
	std::string madeGeometry(IGeomDispatcher& ig2, const shared_ptr<Body>& b1, const shared_ptr<Body>& b2)
	{
		try {
			const shared_ptr<Interaction> probe = ig2.explicitAction(b1, b2, /*force*/ true);
			return probe->geom ? probe->geom->getClassName() : std::string("none");
		} catch (const std::exception&) { // no functor for these shapes
			return "none";
		}
	}
}

long MesoContactStore::restore()
{
	Scene* sc       = Omega::instance().getScene().get();
	long   restored = 0;
	if (from.lock().get() != sc) kept.clear();
	// Checked before any is given back: a refused restore changes nothing and keeps the contacts.
	if (Ip2_MesoMat_MesoMat_MesoPhys* ip2 = mesoPhysOf(*sc)) {
		for (const auto& k : kept) {
			const auto* phys = dynamic_cast<const MesoPhys*>(k.phys.get());
			if (!phys || !phys->pairParams || !sc->bodies->exists(k.id1) || !sc->bodies->exists(k.id2)) continue;
			const auto* m1 = dynamic_cast<const MesoMat*>(Body::byId(k.id1, sc)->material.get());
			const auto* m2 = dynamic_cast<const MesoMat*>(Body::byId(k.id2, sc)->material.get());
			if (!m1 || !m2) continue;
			const std::string differs
			        = meso::firstDifference(ip2->mix(*m1, *m2, dynamic_cast<const ScGeom6D*>(k.geom.get()) != nullptr), phys->pair());
			if (!differs.empty())
				throw std::invalid_argument(
				        "restore: contact #" + std::to_string(k.id1) + "+#" + std::to_string(k.id2) + " carries another " + differs
				        + " than its bodies' materials give that pair here: the contacts come from a scene with other materials "
				          "(give the bodies those materials, or let the pairs start afresh); nothing was restored");
		}
	}
	if (IGeomDispatcher* ig2 = geometryOf(*sc)) {
		std::map<std::pair<int, int>, std::string> made; // by shape classes: one probe each
		for (const auto& k : kept) {
			if (!k.geom || !sc->bodies->exists(k.id1) || !sc->bodies->exists(k.id2)) continue;
			const shared_ptr<Body>& b1  = Body::byId(k.id1, sc);
			const shared_ptr<Body>& b2  = Body::byId(k.id2, sc);
			const auto              key = std::make_pair(b1->shape->getClassIndex(), b2->shape->getClassIndex());
			if (!made.count(key)) made[key] = madeGeometry(*ig2, b1, b2);
			if (made[key] != k.geom->getClassName())
				throw std::invalid_argument(
				        "restore: contact #" + std::to_string(k.id1) + "+#" + std::to_string(k.id2) + " holds a " + k.geom->getClassName()
				        + ", but this scene's InteractionLoop makes a " + made[key]
				        + " for that pair: the contacts come from a scene with other Ig2 functors; nothing was restored");
		}
	}
	for (const auto& k : kept) {
		if (!sc->bodies->exists(k.id1) || !sc->bodies->exists(k.id2)) continue; // a body not on this rank (or no such id)
		const shared_ptr<Interaction>& I = sc->interactions->find(k.id1, k.id2);
		if (!I || I->geom || I->phys) continue;   // no candidate pair here, or one that kept its state
		if (I->getId1() != k.id1) I->swapOrder(); // allowed while it has neither
		I->geom = k.geom;
		I->phys = k.phys;
		++restored;
	}
	kept.clear();
	return restored;
}

// Serialized with the scene's own binary archive (what O.save writes), so every field that survives
// save/load survives the trip to another rank.
boost::python::object MesoContactStore::exportContacts(const boost::python::object& ids) const
{
	if (!PyObject_HasAttrString(ids.ptr(), "__iter__") || PyUnicode_Check(ids.ptr()) || PyBytes_Check(ids.ptr())
	    || PyDict_Check(ids.ptr())) // a dict's keys or its values? neither is assumed
		pychecks::typeError("ids = " + pychecks::describe(ids) + " is invalid: must be a sequence or set of body ids");
	std::set<Body::id_t> wanted;
	long                 k = 0;
	for (boost::python::stl_input_iterator<boost::python::object> it(ids), end; it != end; ++it, ++k)
		wanted.insert(pychecks::id(("ids[" + std::to_string(k) + "]").c_str(), *it));
	std::vector<shared_ptr<Interaction>> contacts;
	for (const auto& I : *Omega::instance().getScene()->interactions)
		if (I->isReal() && (wanted.count(I->getId1()) || wanted.count(I->getId2()))) contacts.push_back(I);
	std::ostringstream out;
	ObjectIO::save<decltype(contacts), boost::archive::binary_oarchive>(out, "contacts", contacts);
	const std::string archive = out.str();
	const std::string bytes   = contactsTag + checksum(archive, 0) + "\n" + archive;
	return boost::python::object(boost::python::handle<>(PyBytes_FromStringAndSize(bytes.data(), static_cast<Py_ssize_t>(bytes.size()))));
}

long MesoContactStore::importContacts(const boost::python::object& data)
{
	char*      buffer = nullptr;
	Py_ssize_t size   = 0;
	if (!PyBytes_Check(data.ptr())) throw std::invalid_argument("data: must be bytes made by MesoContactStore.exportContacts");
	if (PyBytes_AsStringAndSize(data.ptr(), &buffer, &size) != 0) boost::python::throw_error_already_set();
	const std::string bytes(buffer, static_cast<size_t>(size));
	if (bytes.compare(0, contactsTag.size(), contactsTag) != 0) throw std::invalid_argument("data: not contacts made by MesoContactStore.exportContacts");
	const std::size_t start = contactsTag.size() + sumDigits + 1;
	if (bytes.size() < start || bytes[start - 1] != '\n' || bytes.compare(contactsTag.size(), sumDigits, checksum(bytes, start)) != 0)
		throw std::invalid_argument("data: damaged contacts (their checksum does not match; made by MesoContactStore.exportContacts?)");
	std::istringstream                   in(bytes.substr(start));
	std::vector<shared_ptr<Interaction>> contacts;
	try {
		ObjectIO::load<decltype(contacts), boost::archive::binary_iarchive>(in, "contacts", contacts);
	} catch (const std::exception& e) { // a broken archive may throw anything from boost or the library
		throw std::invalid_argument(std::string("data: not contacts made by MesoContactStore.exportContacts (") + e.what() + ")");
	}
	if (in.peek() != std::char_traits<char>::eof()) // bytes appended to an export: not what exportContacts made
		throw std::invalid_argument("data: not contacts made by MesoContactStore.exportContacts (trailing bytes after the contacts)");
	keepFor(Omega::instance().getScene());
	for (const auto& I : contacts)
		kept.push_back({ I->getId1(), I->getId2(), I->geom, I->phys });
	return static_cast<long>(contacts.size());
}

} // namespace yade
