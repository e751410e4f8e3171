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

/// The objects of a scene, held as shared immutable pointers and read as a list of objects.
/// Reading neither allocates nor locks; only push_back() and reserve() allocate.
class CollisionObjectList
{
public:
  /// How the list holds an object: shared with every other list that holds it.
  using Pointer = std::shared_ptr<const CollisionObject>;

  /// Iterates over the objects themselves (dereferencing the pointers).
  class const_iterator
  {
  public:
    /// Tagged random access for the standard algorithms, though only ++ and - are defined.
    using iterator_category = std::random_access_iterator_tag;
    /// The element type: an object, not a pointer.
    using value_type = CollisionObject;
    /// The type of the distance between two iterators.
    using difference_type = std::ptrdiff_t;
    /// What operator->() returns.
    using pointer = const CollisionObject*;
    /// What operator*() returns.
    using reference = const CollisionObject&;

    const_iterator() = default;
    /// An iterator at the pointer `at` of the list's storage.
    explicit const_iterator(std::vector<Pointer>::const_iterator at)
      : m_at(at)
    {}
    /// The object.
    reference operator*() const { return **m_at; }
    /// The object's address.
    pointer operator->() const { return m_at->get(); }
    /// Moves to the next object.
    const_iterator& operator++()
    {
      ++m_at;
      return *this;
    }
    /// Moves to the next object and returns the iterator as it was.
    const_iterator operator++(int)
    {
      const_iterator before = *this;
      ++m_at;
      return before;
    }
    /// The number of objects from `other` to this iterator.
    difference_type operator-(const const_iterator& other) const { return m_at - other.m_at; }
    /// True when both are at the same position of the same list.
    bool operator==(const const_iterator& other) const { return m_at == other.m_at; }
    /// True when they are at different positions.
    bool operator!=(const const_iterator& other) const { return m_at != other.m_at; }

  private:
    std::vector<Pointer>::const_iterator m_at;
  };

  /// Number of objects.
  std::size_t size() const { return m_objects.size(); }
  /// True when the list holds no object.
  bool empty() const { return m_objects.empty(); }
  /// Object `index` (unchecked: it must be below size()).
  const CollisionObject& operator[](std::size_t index) const { return *m_objects[index]; }
  /// The first object (the list must not be empty).
  const CollisionObject& front() const { return *m_objects.front(); }
  /// The last object (the list must not be empty).
  const CollisionObject& back() const { return *m_objects.back(); }
  /// An iterator at the first object.
  const_iterator begin() const { return const_iterator(m_objects.cbegin()); }
  /// An iterator past the last object.
  const_iterator end() const { return const_iterator(m_objects.cend()); }

  /// The shared pointer itself, to put the same object into another scene.
  const Pointer& shared(std::size_t index) const { return m_objects[index]; }

  /// Appends an object (never null). Not for the haptic thread: it may allocate.
  void push_back(Pointer object)
  {
    assert(object != nullptr);
    m_objects.push_back(std::move(object));
  }
  /// Makes room for `count` objects. Not for the haptic thread: it may allocate.
  void reserve(std::size_t count) { m_objects.reserve(count); }

private:
  std::vector<Pointer> m_objects;
};

} // namespace proxima
