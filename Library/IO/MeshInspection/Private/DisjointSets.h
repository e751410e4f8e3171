// Union-find over vertex numbers, with path halving: the groups of the inspection (pieces,
// boundary loops) and of the tool's reach (unreachable regions).
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace proxima
{

class DisjointSets
{
public:
  explicit DisjointSets(std::size_t size)
    : m_parent(size)
  {
    std::iota(m_parent.begin(), m_parent.end(), std::uint32_t{0});
  }
  std::uint32_t find(std::uint32_t i)
  {
    while (m_parent[i] != i)
    {
      m_parent[i] = m_parent[m_parent[i]];
      i = m_parent[i];
    }
    return i;
  }
  void unite(std::uint32_t a, std::uint32_t b) { m_parent[find(a)] = find(b); }

private:
  std::vector<std::uint32_t> m_parent;
};

} // namespace proxima
