// The --listen address of `proxima serve` (Documentation/Server.md): a port from 0 to 65535 (gRPC
// itself wraps 99999 to 34463), the documented 50051 when none is given (gRPC's own default is
// 443), and every loopback address taken as one: 127.0.0.0/8, localhost, [::1].
#include "IO/InputChecks/InputError.h"
#include "Net/RemoteRuns.h"

#include <gtest/gtest.h>

#include <string>

namespace proxima
{
namespace
{
std::string refusal(const std::string& text)
{
  try
  {
    parseListenAddress(text);
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  return "accepted";
}

TEST(ListenAddress, HostAndPort)
{
  const ListenAddress address = parseListenAddress("127.0.0.1:6000");
  EXPECT_EQ(address.host, "127.0.0.1");
  EXPECT_EQ(address.port, 6000);
  EXPECT_TRUE(address.loopback);
  EXPECT_EQ(address.hostAndPort(), "127.0.0.1:6000");
  EXPECT_EQ(parseListenAddress("0.0.0.0:0").port, 0);
  EXPECT_EQ(parseListenAddress("0.0.0.0:65535").port, 65535);
}

TEST(ListenAddress, AHostAloneTakesTheDocumentedPort)
{
  EXPECT_EQ(parseListenAddress("127.0.0.1").hostAndPort(), "127.0.0.1:50051");
  EXPECT_EQ(parseListenAddress("localhost").hostAndPort(), "localhost:50051");
  EXPECT_EQ(parseListenAddress("[::1]").hostAndPort(), "[::1]:50051");
}

TEST(ListenAddress, PortsOutOfRangeOrMalformedAreRefused)
{
  EXPECT_EQ(refusal("127.0.0.1:99999"),
            "--listen: '127.0.0.1:99999' has port 99999, out of range: give 0 to 65535 (0 takes a "
            "free one)");
  EXPECT_EQ(refusal("127.0.0.1:65536"),
            "--listen: '127.0.0.1:65536' has port 65536, out of range: give 0 to 65535 (0 takes a "
            "free one)");
  for (const char* text :
       {"127.0.0.1:", "127.0.0.1:-1", "127.0.0.1:80x", "127.0.0.1:1e3", "[::1]:", "[::1]:http"})
  {
    EXPECT_NE(refusal(text).find("has no port number after ':'"), std::string::npos)
      << text << ": " << refusal(text);
  }
  EXPECT_NE(refusal("127.0.0.1:4294967297").find("out of range"), std::string::npos);
  EXPECT_EQ(parseListenAddress("127.0.0.1:000080").port, 80);
  EXPECT_NE(refusal(":50051").find("has no host"), std::string::npos);
  EXPECT_NE(refusal("").find("has no host"), std::string::npos);
  EXPECT_NE(refusal("::1").find("write an IPv6 address in brackets"), std::string::npos);
  EXPECT_NE(refusal("[::1").find("has no ']'"), std::string::npos);
  EXPECT_NE(refusal("[::1]50051").find("other than ':PORT'"), std::string::npos);
}

TEST(ListenAddress, EveryLoopbackAddressIsLoopback)
{
  for (const char* text :
       {"127.0.0.1:1", "127.0.0.2:50051", "127.255.255.254:0", "127.1.2.3", "localhost:7",
        "[::1]:50051", "[::1]", "[0:0:0:0:0:0:0:1]:9", "[::ffff:127.0.0.5]:9"})
  {
    EXPECT_TRUE(parseListenAddress(text).loopback) << text;
    EXPECT_TRUE(isLoopbackAddress(text)) << text;
  }
  for (const char* text :
       {"0.0.0.0:50051", "128.0.0.1:1", "10.0.0.1:1", "[::]:1", "[::2]:1", "126.255.255.255:1",
        "example.org:1", "[::ffff:10.0.0.1]:1", "127.0.0.1.example.org:1"})
  {
    EXPECT_FALSE(parseListenAddress(text).loopback) << text;
  }
  // An address that cannot be read is not loopback.
  EXPECT_FALSE(isLoopbackAddress("127.0.0.1:99999"));
}
} // namespace
} // namespace proxima
