// The objects of a collision scene as shared, immutable pointers that read as a list of objects:
// `objects[i].mesh`, `for (const CollisionObject& object : objects)`. Two scenes that hold the
// same object share it, so a new scene after an edit costs one pointer per unchanged object,
// not a copy of its mesh and tree. Reading allocates nothing and takes no lock (the proxy update
// reads it every tick); only building a list (push_back) allocates.
#pragma once

#include "Proxy/CollisionObject.h"

#include <cassert>
#include <cstddef>
#include <iterator>
#include <memory>
#include <vector>

namespace proxima
{

class CollisionObjectList
{
public:
  using Pointer = std::shared_ptr<const CollisionObject>;

  /// Iterates over the objects themselves (dereferencing the pointers).
  class const_iterator
  {
  public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = CollisionObject;
    using difference_type = std::ptrdiff_t;
    using pointer = const CollisionObject*;
    using reference = const CollisionObject&;

    const_iterator() = default;
    explicit const_iterator(std::vector<Pointer>::const_iterator at)
      : m_at(at)
    {}
    reference operator*() const { return **m_at; }
    pointer operator->() const { return m_at->get(); }
    const_iterator& operator++()
    {
      ++m_at;
      return *this;
    }
    const_iterator operator++(int)
    {
      const_iterator before = *this;
      ++m_at;
      return before;
    }
    difference_type operator-(const const_iterator& other) const { return m_at - other.m_at; }
    bool operator==(const const_iterator& other) const { return m_at == other.m_at; }
    bool operator!=(const const_iterator& other) const { return m_at != other.m_at; }

  private:
    std::vector<Pointer>::const_iterator m_at;
  };

  std::size_t size() const { return m_objects.size(); }
  bool empty() const { return m_objects.empty(); }
  const CollisionObject& operator[](std::size_t index) const { return *m_objects[index]; }
  const CollisionObject& front() const { return *m_objects.front(); }
  const CollisionObject& back() const { return *m_objects.back(); }
  const_iterator begin() const { return const_iterator(m_objects.cbegin()); }
  const_iterator end() const { return const_iterator(m_objects.cend()); }

  /// The shared pointer itself, to put the same object into another scene.
  const Pointer& shared(std::size_t index) const { return m_objects[index]; }

  /// Appends an object (never null). Not for the haptic thread: it may allocate.
  void push_back(Pointer object)
  {
    assert(object != nullptr);
    m_objects.push_back(std::move(object));
  }
  void reserve(std::size_t count) { m_objects.reserve(count); }

private:
  std::vector<Pointer> m_objects;
};

} // namespace proxima
