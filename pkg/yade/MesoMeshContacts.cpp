#include "MesoMeshContacts.hpp"

namespace yade {

void MesoMeshContacts::put(Id sphere, Id holder, Id at, long iter)
{
	std::vector<Entry>& entries = bySphere[sphere];
	for (Entry& e : entries)
		if (e.holder == holder) {
			e.at   = at;
			e.iter = iter;
			return;
		}
	entries.push_back(Entry { holder, at, iter });
}

void MesoMeshContacts::record(Id sphere, Id holder, Id at, long iter)
{
	const std::lock_guard<std::mutex> lock(mutex);
	put(sphere, holder, at, iter);
}

MesoMeshContacts::Id MesoMeshContacts::at(Id sphere, Id holder, long iter, std::vector<Entry>& others)
{
	others.clear();
	Id                                where = holder;
	const std::lock_guard<std::mutex> lock(mutex);
	const auto                        found = bySphere.find(sphere);
	if (found != bySphere.end())
		for (const Entry& e : found->second)
			if (e.holder == holder) where = e.at;
			else if (e.iter >= iter - 1)
				others.push_back(e);
	return where;
}

void MesoMeshContacts::forget(Id sphere, Id holder)
{
	const std::lock_guard<std::mutex> lock(mutex);
	const auto                        found = bySphere.find(sphere);
	if (found == bySphere.end()) return;
	std::vector<Entry>& entries = found->second;
	for (std::size_t k = 0; k < entries.size(); ++k)
		if (entries[k].holder == holder) {
			entries[k] = entries.back();
			entries.pop_back();
			break;
		}
	if (entries.empty()) bySphere.erase(found);
}

void MesoMeshContacts::others(Id sphere, Id holder, long iter, std::vector<Entry>& out)
{
	out.clear();
	const std::lock_guard<std::mutex> lock(mutex);
	const auto                        found = bySphere.find(sphere);
	if (found == bySphere.end()) return;
	for (const Entry& e : found->second)
		if (e.holder != holder && e.iter >= iter - 1) out.push_back(e);
}

} // namespace yade
