// The per-query cache of paper section 5: several leaf spheres cover one triangle, and the exact
// test runs once per triangle per query. A fixed open-addressing set, cleared in O(1) by a
// generation counter; when it is full, triangles are simply tested again (correct, slower), and a
// query that collects results (gatherWithin) checks `full()` to keep them free of duplicates.
#pragma once

#include <cstdint>

namespace proxima
{

/// The set of triangles already tested in one query, so that a triangle covered by several leaf
/// spheres gets its exact test once. Fixed size, never allocates; one per querying thread.
class TriangleTestCache
{
public:
  /// Slots of the open-addressing table (a power of two, for the mask).
  static constexpr std::uint32_t kSlots = 4096;
  /// Triangles the set holds before it counts as full: half the slots, to keep probes short.
  static constexpr std::uint32_t kMaxEntries = kSlots / 2;

  /// Starts a new query: everything inserted before is forgotten.
  void clear()
  {
    ++m_generation;
    m_numEntries = 0;
    if (m_generation == 0)
    {
      // The counter wrapped: wipe the slots once so stale generations cannot match.
      for (Slot& slot : m_slots)
      {
        slot = Slot{};
      }
      m_generation = 1;
    }
  }

  /// True once the set holds kMaxEntries triangles: insert() then answers true for every triangle.
  bool full() const { return m_numEntries >= kMaxEntries; }

  /// True if `triangle` was not yet in the set (it is now), or if the set is full; false if it
  /// was already tested.
  bool insert(std::uint32_t triangle)
  {
    if (m_numEntries >= kMaxEntries)
    {
      return true;
    }
    std::uint32_t slot = (triangle * 2654435761u) & (kSlots - 1);
    while (m_slots[slot].generation == m_generation)
    {
      if (m_slots[slot].triangle == triangle)
      {
        return false;
      }
      slot = (slot + 1) & (kSlots - 1);
    }
    m_slots[slot].generation = m_generation;
    m_slots[slot].triangle = triangle;
    ++m_numEntries;
    return true;
  }

private:
  struct Slot
  {
    std::uint32_t generation = 0;
    std::uint32_t triangle = 0;
  };
  Slot m_slots[kSlots];
  std::uint32_t m_generation = 1;
  std::uint32_t m_numEntries = 0;
};

} // namespace proxima
