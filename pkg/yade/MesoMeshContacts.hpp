// Which facet each sphere-facet contact lies on now. A contact with a mesh of facets is held, for
// its whole life, by the interaction that made it (its "holder"); it travels across the edges and
// vertices of the mesh with the sphere, so its history goes where the contact goes. The holders'
// threads write here and the other facets' threads read here (never each other's interactions,
// which YADE's OpenMP loop may be resetting): a facet about to make a contact first asks whether
// one of the sphere's holders already stands on it.
#pragma once
#include <atomic>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace yade {

class Scene;

// Free of YADE's headers (they cost a minute and a half per translation unit): ids are YADE's Body::id_t.
class MesoMeshContacts {
public:
	using Id = int;
	struct Entry {
		Id   holder; // the facet whose interaction holds the contact
		Id   at;     // the facet the contact lies on now
		long iter;   // the step of the last update; older than the last step: a contact gone
	};
	// Called first by every geometry call: a new step carries the table over; a load, a new
	// scene or a gap in the steps rebuilds it (rebuild(table) fills it from the real interactions).
	template <class Rebuild> void beginStep(const Scene* scene, long iter, Rebuild&& rebuild)
	{
		if (seenIter.load(std::memory_order_acquire) == iter && seenScene == scene) return;
		const std::lock_guard<std::mutex> lock(mutex);
		const long                        seen = seenIter.load(std::memory_order_relaxed);
		if (seen == iter && seenScene == scene) return;
		if (!(seenScene == scene && seen == iter - 1)) {
			bySphere.clear();
			rebuild(*this, iter);
		}
		seenScene = scene;
		seenIter.store(iter, std::memory_order_release);
	}
	// Where the holder's contact lay at the last update (the holder itself if unknown); others: the
	// sphere's other contacts updated at iter - 1 or later (one lock for both, once per step).
	Id   at(Id sphere, Id holder, long iter, std::vector<Entry>& others);
	void record(Id sphere, Id holder, Id at, long iter);
	void forget(Id sphere, Id holder);
	// The contacts of the sphere held by other facets, updated at iter - 1 or later.
	void others(Id sphere, Id holder, long iter, std::vector<Entry>& out);
	// record() without the lock: for rebuild only, which runs under it.
	void put(Id sphere, Id holder, Id at, long iter);

private:
	std::mutex                                 mutex;
	std::unordered_map<Id, std::vector<Entry>> bySphere;
	std::atomic<long>                          seenIter { -2 };
	const Scene*                               seenScene = nullptr;
};

} // namespace yade
