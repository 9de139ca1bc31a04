// The motion of each body's contact neighbours, summed for MesoBackgroundDamping's contact-relative
// reference. The law adds every contact it visits (one sum per thread, no locks), so the drag needs
// no second pass over the interactions; the engine's own pass (sumPair over the container) is the
// fallback, with the same arithmetic in the same order.
#pragma once
#include <core/Interaction.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <algorithm>
#include <atomic>
#include <vector>
#ifdef YADE_OPENMP
#include <omp.h>
#endif

namespace yade {

struct MesoNeighbourSums {
	struct Sums {
		Vector3r x = Vector3r::Zero(), v = Vector3r::Zero(), w = Vector3r::Zero(); // positions, velocities, spins
		int      n = 0;
	};
	std::vector<std::vector<Sums>> perThread; // [thread][body id]
	// The scene->iter the sums are zeroed for (the law adds only then); -1 after a contact the sums
	// could not take, so that the engine sums itself this step.
	std::atomic<long> step { -1 };

	static int thread()
	{
#ifdef YADE_OPENMP
		return omp_get_thread_num();
#else
		return 0;
#endif
	}

	// Each body of a contact in overlap adds the other's motion: a sphere's centre, or for a wall
	// (no radius) the material point at the contact. Across a periodic boundary the other body is
	// its image next to this one (position and velocity shifted by the cell).
	static void
	sumPair(std::vector<Sums>& acc,
	        const Interaction& I,
	        const ScGeom&      geom,
	        const State&       s1,
	        const State&       s2,
	        bool               sphere1,
	        bool               sphere2,
	        const Scene*       scene)
	{
		Vector3r shift = Vector3r::Zero(), shiftVel = Vector3r::Zero(); // of body 2's image next to body 1
		if (scene->isPeriodic && I.cellDist != Vector3i::Zero()) {      // most contacts do not cross
			shift    = scene->cell->hSize * I.cellDist.cast<Real>();
			shiftVel = scene->cell->intrShiftVel(I.cellDist);
		}
		const Vector3r& c = geom.contactPoint; // in body 1's frame
		Sums&           a = acc[I.getId1()];   // body 1 sees body 2's image
		if (sphere2) {
			a.x += s2.pos + shift;
			a.v += s2.vel + shiftVel;
		} else {
			a.x += c;
			a.v += s2.vel + shiftVel + s2.angVel.cross(c - (s2.pos + shift));
		}
		a.w += s2.angVel;
		++a.n;
		Sums& b = acc[I.getId2()]; // body 2 sees body 1's image
		if (sphere1) {
			b.x += s1.pos - shift;
			b.v += s1.vel - shiftVel;
		} else {
			b.x += c - shift;
			b.v += s1.vel - shiftVel + s1.angVel.cross(c - s1.pos);
		}
		b.w += s1.angVel;
		++b.n;
	}

	// Called by the law for every contact it visits (sphereK: body K is a sphere).
	void add(const Interaction& I, const ScGeom& geom, const State& s1, const State& s2, bool sphere1, bool sphere2, const Scene* scene)
	{
		if (step.load(std::memory_order_relaxed) != scene->iter || !(geom.penetrationDepth > 0)) return;
		const size_t t = static_cast<size_t>(thread());
		// More threads than the engine sized for, or a body added since: the engine sums itself.
		if (t >= perThread.size() || static_cast<size_t>(std::max(I.getId1(), I.getId2())) >= perThread[t].size()) {
			step.store(-1, std::memory_order_relaxed);
			return;
		}
		sumPair(perThread[t], I, geom, s1, s2, sphere1, sphere2, scene);
	}
};

} // namespace yade
