// proxima._proxima.HapticClient: the C++ live client (Net/HapticClient.h) for Python, which
// proxima.haptic_client wraps in its Pythonic names. Everything the client does on the wire
// (connecting, bundling a scene file, splitting a large shape, ownership, the token, TLS,
// reconnecting) is the C++ client's; here are only the conversions: numpy arrays to shapes,
// samples to dicts, and the C++ client's errors to Python's (ConnectionError, PermissionError,
// OwnershipEnded, ValueError, IndexError). The stream's samples arrive on the C++ client's
// thread, which never touches Python: they wait in a queue here for the Python generator.
#include "Bindings.h"

#include "Net/HapticClient.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace proxima::python
{
namespace
{

// Python's exceptions for the client's errors; OwnershipEnded is registered by addHapticClient.
PyObject* g_ownershipEnded = nullptr;

// Runs `call` with the GIL released (it may wait on the network) and raises the Python exception
// that the C++ client's error stands for.
template <typename Call>
auto guarded(Call&& call) -> decltype(call())
{
  try
  {
    py::gil_scoped_release released;
    return call();
  }
  catch (const OwnershipEnded& error)
  {
    PyErr_SetString(g_ownershipEnded, error.defect().c_str());
  }
  catch (const ServerUnavailable& error)
  {
    PyErr_SetString(PyExc_ConnectionError, error.defect().c_str());
  }
  catch (const ServerRefused& error)
  {
    PyErr_SetString(PyExc_PermissionError, error.defect().c_str());
  }
  catch (const std::invalid_argument& error)
  {
    PyErr_SetString(PyExc_ValueError, error.what());
  }
  throw py::error_already_set();
}

// The samples the C++ client's stream thread hands over, each with the touch changes seen before
// it, until the Python generator takes them. Bounded: a reader that stops reading without ending
// the stream loses the oldest samples, not the machine's memory.
class SampleQueue
{
public:
  static constexpr std::size_t kCapacity = 1u << 16;

  struct Entry
  {
    LiveSample sample;
    std::vector<TouchChange> touches;
  };

  void touch(const TouchChange& change)
  {
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_touches.push_back(change);
  }

  void push(const LiveSample& sample)
  {
    {
      const std::lock_guard<std::mutex> lock(m_mutex);
      if (m_entries.size() == kCapacity)
      {
        m_entries.pop_front();
      }
      m_entries.push_back({sample, std::move(m_touches)});
      m_touches.clear();
    }
    m_arrived.notify_one();
  }

  /// The oldest sample, waiting at most `timeout` for one; false when none came.
  bool pop(Entry& entry, std::chrono::milliseconds timeout)
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    if (!m_arrived.wait_for(lock, timeout, [this] { return !m_entries.empty(); }))
    {
      return false;
    }
    entry = std::move(m_entries.front());
    m_entries.pop_front();
    return true;
  }

  void clear()
  {
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_entries.clear();
    m_touches.clear();
  }

private:
  std::mutex m_mutex;
  std::condition_variable m_arrived;
  std::deque<Entry> m_entries;
  std::vector<TouchChange> m_touches;
};

// A pose as the 4x4 matrix M with M (p, 1) = pose.apply(p).
py::array_t<double> poseMatrix(const RigidTransform& pose)
{
  py::array_t<double> matrix({4, 4});
  auto m = matrix.mutable_unchecked<2>();
  for (int i = 0; i < 4; ++i)
  {
    const Vec3 row = i < 3 ? pose.row[i] : Vec3{0.0, 0.0, 0.0};
    m(i, 0) = row.x;
    m(i, 1) = row.y;
    m(i, 2) = row.z;
    m(i, 3) = i < 3 ? (i == 0   ? pose.translation.x
                       : i == 1 ? pose.translation.y
                                : pose.translation.z)
                    : 1.0;
  }
  return matrix;
}

py::dict sampleDict(const SampleQueue::Entry& entry)
{
  const LiveSample& sample = entry.sample;
  py::dict result;
  result["tick"] = sample.tick;
  result["t"] = sample.time;
  result["finger"] = vectorArray(sample.finger);
  result["proxy"] = vectorArray(sample.proxy);
  result["force"] = vectorArray(sample.force);
  result["contacts"] = sample.contacts;
  result["shape"] = sample.shape;
  result["flags"] = sample.flags;
  result["model_version"] = sample.modelVersion;
  py::list events;
  for (const TouchChange& change : entry.touches)
  {
    events.append(py::make_tuple(change.shape, change.touched));
  }
  result["events"] = events;
  result["dropped_samples"] = sample.droppedSamples;
  py::list bodies;
  for (const LiveBodyPose& body : sample.bodies)
  {
    bodies.append(py::make_tuple(body.shape, poseMatrix(body.pose)));
  }
  result["bodies"] = bodies;
  result["latency_ms"] =
    static_cast<double>(sample.receivedNanoseconds - sample.sentNanoseconds) / 1e6;
  result["reconnections"] = sample.reconnections;
  return result;
}

// A 4x4 rigid motion (a rotation and a translation, last row 0 0 0 1), else ValueError: the
// server's shapes move rigidly, and a scaled or sheared matrix would be silently wrong.
RigidTransform rigidFrom(const py::array_t<double, py::array::c_style | py::array::forcecast>& in)
{
  if (in.ndim() != 2 || in.shape(0) != 4 || in.shape(1) != 4)
  {
    throw py::value_error("mult_matrix: a 4x4 matrix");
  }
  const auto m = in.unchecked<2>();
  RigidTransform transform;
  for (int i = 0; i < 3; ++i)
  {
    transform.row[i] = {m(i, 0), m(i, 1), m(i, 2)};
  }
  transform.translation = {m(0, 3), m(1, 3), m(2, 3)};
  double worst =
    std::abs(m(3, 0)) + std::abs(m(3, 1)) + std::abs(m(3, 2)) + std::abs(m(3, 3) - 1.0);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      worst = std::max(worst, std::abs(dot(transform.row[i], transform.row[j]) - (i == j)));
    }
  }
  const double determinant = dot(transform.row[0], cross(transform.row[1], transform.row[2]));
  if (!(worst <= 1e-9) || !(determinant > 0.0))
  {
    throw py::value_error("mult_matrix: not a rigid motion (a rotation and a translation, the "
                          "last row 0 0 0 1)");
  }
  return transform;
}

// The client, its stream's queue, and what Python asked of it.
class PythonHapticClient
{
public:
  PythonHapticClient(const std::string& server, const std::string& token, bool owner,
                     const std::string& tlsCa, double reconnectSeconds, double timeoutSeconds)
  {
    ServerConnection connection;
    connection.server = server;
    connection.token = token;
    if (!tlsCa.empty())
    {
      std::ifstream file(tlsCa, std::ios::binary);
      std::ostringstream text;
      text << file.rdbuf();
      if (!file)
      {
        throw py::value_error("tls_ca: cannot read " + tlsCa);
      }
      connection.tlsRootCertificates = text.str();
    }
    connection.reconnect.maxWait = std::chrono::milliseconds(
      static_cast<std::int64_t>(std::max(reconnectSeconds, 0.0) * 1000.0));
    connection.connectTimeout = std::chrono::milliseconds(
      static_cast<std::int64_t>(std::max(timeoutSeconds, 0.001) * 1000.0));
    const HapticClientRole role = owner ? HapticClientRole::Owner : HapticClientRole::Observer;
    m_client = guarded([&] { return std::make_unique<HapticClient>(connection, role); });
  }

  HapticClient& client()
  {
    if (m_client == nullptr)
    {
      throw py::value_error("the client is closed");
    }
    return *m_client;
  }

  void shape(const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
             const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& triangles,
             const py::object& normals, const py::object& textureCoordinates,
             const std::string& name)
  {
    if (points.ndim() != 2 || points.shape(1) != 3)
    {
      throw py::value_error("shape: points are an (N, 3) array");
    }
    if (triangles.ndim() != 2 || triangles.shape(1) != 3)
    {
      throw py::value_error("shape: triangles are an (M, 3) array of point indices");
    }
    using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
    const py::ssize_t count = points.shape(0);
    // A default array_t is an empty one-dimensional array, not a null handle: whether each was
    // given is kept apart.
    const bool hasNormals = !normals.is_none();
    const bool hasTextureCoordinates = !textureCoordinates.is_none();
    Doubles normalArray;
    Doubles uvArray;
    if (hasNormals)
    {
      normalArray = Doubles::ensure(normals);
      if (!normalArray || normalArray.ndim() != 2 || normalArray.shape(0) != count ||
          normalArray.shape(1) != 3)
      {
        throw py::value_error("shape: normals are an (N, 3) array, one per point");
      }
    }
    if (hasTextureCoordinates)
    {
      uvArray = Doubles::ensure(textureCoordinates);
      if (!uvArray || uvArray.ndim() != 2 || uvArray.shape(0) != count || uvArray.shape(1) != 2)
      {
        throw py::value_error("shape: texture coordinates are an (N, 2) array, one per point");
      }
    }
    const auto p = points.unchecked<2>();
    const auto t = triangles.unchecked<2>();
    for (py::ssize_t i = 0; i < triangles.shape(0); ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        // Out-of-range indices are the server's to refuse, by name, as the C++ client's are;
        // here only what an index of the wire's type cannot hold.
        if (t(i, k) < 0 || t(i, k) > 0xffffffffLL)
        {
          throw py::value_error("shape: triangle " + std::to_string(i) +
                                " has a point index no uint32 holds");
        }
      }
    }
    HapticClient& live = client();
    live.beginShape(name);
    for (py::ssize_t i = 0; i < count; ++i)
    {
      if (hasNormals)
      {
        const auto n = normalArray.unchecked<2>();
        live.normal({n(i, 0), n(i, 1), n(i, 2)});
      }
      if (hasTextureCoordinates)
      {
        const auto uv = uvArray.unchecked<2>();
        live.texCoord(uv(i, 0), uv(i, 1));
      }
      live.vertex({p(i, 0), p(i, 1), p(i, 2)});
    }
    for (py::ssize_t i = 0; i < triangles.shape(0); ++i)
    {
      live.triangle(static_cast<std::uint32_t>(t(i, 0)), static_cast<std::uint32_t>(t(i, 1)),
                    static_cast<std::uint32_t>(t(i, 2)));
    }
    live.endShape();
  }

  py::dict commit()
  {
    HapticClient& live = client();
    const ModelReceiptInfo receipt = guarded([&] { return live.commit(); });
    py::dict result;
    result["version"] = receipt.version;
    result["shapes"] = receipt.shapes;
    result["triangles"] = receipt.triangles;
    result["build_ms"] = receipt.buildMilliseconds;
    result["live_ms"] = receipt.liveMilliseconds;
    return result;
  }

  void startStream(double rateHz)
  {
    HapticClient& live = client();
    guarded([&] { static_cast<void>(live.stopStateStream()); });
    m_samples.clear();
    guarded([&] {
      live.startStateStream(
        rateHz, [this](const LiveSample& sample) { m_samples.push(sample); },
        [this](const TouchChange& change) { m_samples.touch(change); });
    });
  }

  /// The next sample as a dict, None when none came within `timeoutSeconds`.
  py::object nextSample(double timeoutSeconds)
  {
    SampleQueue::Entry entry;
    bool arrived = false;
    {
      py::gil_scoped_release released;
      arrived = m_samples.pop(entry, std::chrono::milliseconds(static_cast<std::int64_t>(
                                       std::max(timeoutSeconds, 0.0) * 1000.0)));
    }
    return arrived ? py::object(sampleDict(entry)) : py::object(py::none());
  }

  void close()
  {
    std::unique_ptr<HapticClient> closing = std::move(m_client);
    // Its destructor ends the stream and the ownership, which waits for the server.
    py::gil_scoped_release released;
    closing.reset();
  }

private:
  // Declared first, so destroyed last: the client's stream thread pushes into it until the
  // client's destructor has joined that thread.
  SampleQueue m_samples;
  std::unique_ptr<HapticClient> m_client;
};

} // namespace

void addHapticClientBindings(py::module_& module)
{
  static py::exception<OwnershipEnded> ownershipEnded(module, "OwnershipEnded",
                                                      PyExc_PermissionError);
  g_ownershipEnded = ownershipEnded.ptr();
  using Client = PythonHapticClient;
  py::class_<Client>(module, "HapticClient",
                     "The C++ live client (Net/HapticClient.h); proxima.haptic_client wraps it.")
    .def(
      py::init<const std::string&, const std::string&, bool, const std::string&, double, double>(),
      py::arg("server"), py::arg("token"), py::arg("owner"), py::arg("tls_ca"),
      py::arg("reconnect"), py::arg("timeout"))
    .def("load_identity", [](Client& c) { c.client().loadIdentity(); })
    .def("push_matrix", [](Client& c) { c.client().pushMatrix(); })
    .def("pop_matrix",
         [](Client& c) {
           try
           {
             c.client().popMatrix();
           }
           catch (const std::logic_error&)
           {
             throw py::index_error("pop_matrix: more pops than pushes");
           }
         })
    .def("mult_matrix",
         [](Client& c, const py::array_t<double, py::array::c_style | py::array::forcecast>& m) {
           c.client().multMatrix(rigidFrom(m));
         })
    .def("translate",
         [](Client& c, double x, double y, double z) {
           c.client().translate({x, y, z});
         })
    .def("rotate",
         [](Client& c, double degrees, double x, double y, double z) {
           guarded([&] { c.client().rotate(degrees, {x, y, z}); });
         })
    .def("material",
         [](Client& c, double stiffness, double staticFriction, double dynamicFriction,
            double viscosity) {
           c.client().material({stiffness, staticFriction, dynamicFriction, viscosity});
         })
    .def("shape", &Client::shape)
    .def("scene", [](Client& c, const std::string& file) { c.client().scene(file); })
    .def("pending_shapes", [](Client& c) { return c.client().pendingShapes(); })
    .def("owns_model", [](Client& c) { return c.client().ownsModel(); })
    .def("ownership_end", [](Client& c) { return c.client().ownershipEnd(); })
    .def("claim_ownership", [](Client& c) { guarded([&] { c.client().claimOwnership(); }); })
    .def("commit", &Client::commit)
    .def("start_stream", &Client::startStream)
    .def("next_sample", &Client::nextSample)
    .def("stream_end", [](Client& c) { return c.client().stateStreamEnd(); })
    .def("stop_stream",
         [](Client& c) {
           HapticClient& live = c.client();
           return guarded([&] { return live.stopStateStream(); });
         })
    .def("close", &Client::close);
}

} // namespace proxima::python
