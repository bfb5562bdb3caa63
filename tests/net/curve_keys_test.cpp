// CURVE certificate files (ZeroMQ's format) and the choice between CURVE, loopback and --insecure,
// without sockets.
#include "net/curve_keys.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "net/curve_setup.h"
#include "net/curve_sockets.h"
#include "temp_dir.h"

namespace {

namespace fs = std::filesystem;

using net_test::TempDir;

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(CurveKeys, WrittenFilesReadBack) {
  TempDir dir;
  const curve::Certificate made = curve::generateCertificate("viewer1", "viewer");
  curve::writeCertificates(dir.path.string(), "viewer1", made);
  const curve::Certificate secret = curve::readCertificate(dir / "viewer1.key_secret", true);
  EXPECT_EQ(secret.public_key, made.public_key);
  EXPECT_EQ(secret.secret_key, made.secret_key);
  EXPECT_EQ(secret.metadata.at("name"), "viewer1");
  EXPECT_EQ(secret.metadata.at("role"), "viewer");
  const curve::Certificate public_only = curve::readCertificate(dir / "viewer1.key");
  EXPECT_EQ(public_only.public_key, made.public_key);
  EXPECT_TRUE(public_only.secret_key.empty()) << "the public certificate must not hold the secret";
  EXPECT_THROW(curve::readCertificate(dir / "viewer1.key", true), curve::CertificateError);
  struct stat st {};
  ASSERT_EQ(::stat((dir / "viewer1.key_secret").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
}

TEST(CurveKeys, NeverOverwritesAndRefusesOddNames) {
  TempDir dir;
  const curve::Certificate made = curve::generateCertificate("a", "operator");
  curve::writeCertificates(dir.path.string(), "a", made);
  EXPECT_THROW(curve::writeCertificates(dir.path.string(), "a", curve::generateCertificate("a", "operator")),
               curve::CertificateError);
  EXPECT_EQ(curve::readCertificate(dir / "a.key_secret", true).secret_key, made.secret_key);
  for (const char* bad : {"", "../a", ".hidden", "a b", "a/b"}) {
    EXPECT_THROW(curve::writeCertificates(dir.path.string(), bad, made), curve::CertificateError) << bad;
  }
}

TEST(CurveKeys, ReadsTheFormatOthersWrite) {
  TempDir dir;
  const curve::Certificate made = curve::generateCertificate("x", "viewer");
  // pyzmq's layout: single quotes nowhere, a comment block, tabs are fine too.
  writeFile(dir / "py.key",
            "#   ****  Generated on 2026-01-01 by pyzmq  ****\n\nmetadata\n\trole = \"operator\"\ncurve\n" +
                std::string("    public-key = \"") + made.public_key + "\"\n");
  const curve::Certificate read = curve::readCertificate(dir / "py.key");
  EXPECT_EQ(read.public_key, made.public_key);
  EXPECT_EQ(read.metadata.at("role"), "operator");
  writeFile(dir / "bad.key", "curve\n    public-key = \"tooshort\"\n");
  EXPECT_THROW(curve::readCertificate(dir / "bad.key"), curve::CertificateError);
  writeFile(dir / "noeq.key", "curve\n    public-key\n");
  EXPECT_THROW(curve::readCertificate(dir / "noeq.key"), curve::CertificateError);
  EXPECT_THROW(curve::readCertificate(dir / "missing.key"), curve::CertificateError);
}

TEST(CurveKeys, AllowListTakesEveryKeyWithItsRole) {
  TempDir dir;
  const curve::Certificate viewer = curve::generateCertificate("v", "viewer");
  const curve::Certificate op = curve::generateCertificate("o", "operator");
  curve::writeCertificates(dir.path.string(), "v", viewer);
  curve::writeCertificates(dir.path.string(), "o", op);
  const curve::AllowList keys = curve::readAllowList(dir.path.string());
  ASSERT_EQ(keys.size(), 2u) << "the .key_secret files are not keys to allow";
  EXPECT_EQ(keys.at(viewer.public_key).role, curve::PeerRole::Viewer);
  EXPECT_EQ(keys.at(op.public_key).role, curve::PeerRole::Operator);
  EXPECT_EQ(keys.at(op.public_key).name, "o");

  curve::writeCertificates(dir.path.string(), "srv", curve::generateCertificate("srv", "server"));
  EXPECT_THROW(curve::readAllowList(dir.path.string()), curve::CertificateError) << "a key without a client role";
  TempDir empty;
  EXPECT_THROW(curve::readAllowList(empty.path.string()), curve::CertificateError);
  EXPECT_THROW(curve::readAllowList(empty / "nowhere"), curve::CertificateError);
}

TEST(CurveSetup, LoopbackEndpoints) {
  for (const char* local : {"tcp://127.0.0.1:5555", "tcp://127.0.0.1:*", "tcp://127.1.2.3:1", "tcp://localhost:5",
                            "tcp://[::1]:5555", "ipc:///tmp/x", "inproc://frames"}) {
    EXPECT_TRUE(curve::isLoopbackEndpoint(local)) << local;
  }
  for (const char* remote : {"tcp://0.0.0.0:5555", "tcp://*:5555", "tcp://eth0:5555", "tcp://192.168.1.2:5555",
                             "tcp://127.example.com:5", "tcp://[::]:5555", "udp://127.0.0.1:5", "tcp://127.0.0.1"}) {
    EXPECT_FALSE(curve::isLoopbackEndpoint(remote)) << remote;
  }
}

TEST(CurveSetup, BeyondLoopbackNeedsCurveOrInsecure) {
  TempDir dir;
  curve::writeCertificates(dir.path.string(), "server", curve::generateCertificate("server", "server"));
  fs::create_directory(dir.path / "clients");
  curve::writeCertificates(dir / "clients", "v", curve::generateCertificate("v", "viewer"));
  const std::vector<std::string> local = {"tcp://127.0.0.1:5555"};
  const std::vector<std::string> remote = {"tcp://127.0.0.1:5555", "tcp://0.0.0.0:5556"};

  EXPECT_FALSE(curve::loadServerSecurity({}, local).own);
  EXPECT_FALSE(curve::loadServerSecurity({}, local).insecure);
  EXPECT_THROW(curve::loadServerSecurity({}, remote), std::invalid_argument);
  curve::ServerFiles insecure;
  insecure.insecure = true;
  EXPECT_TRUE(curve::loadServerSecurity(insecure, remote).insecure);
  EXPECT_FALSE(curve::loadServerSecurity(insecure, local).insecure) << "loopback is not insecure";

  curve::ServerFiles files{dir / "server.key_secret", dir / "clients", false};
  const curve::ServerSecurity secure = curve::loadServerSecurity(files, remote);
  ASSERT_TRUE(secure.own);
  EXPECT_EQ(secure.clients.size(), 1u);
  EXPECT_FALSE(secure.insecure);
  files.insecure = true;
  EXPECT_THROW(curve::loadServerSecurity(files, remote), std::invalid_argument);
  EXPECT_THROW(curve::loadServerSecurity({dir / "server.key_secret", "", false}, local), std::invalid_argument);
  EXPECT_THROW(curve::loadServerSecurity({dir / "server.key", dir / "clients", false}, local), curve::CertificateError)
      << "the public certificate has no secret key";

  EXPECT_FALSE(curve::loadClientFiles({}));
  EXPECT_THROW(curve::loadClientFiles({dir / "clients/v.key_secret", ""}), std::invalid_argument);
  const auto client = curve::loadClientFiles({dir / "clients/v.key_secret", dir / "server.key"});
  ASSERT_TRUE(client);
  EXPECT_EQ(client->server_key, curve::readCertificate(dir / "server.key").public_key);
}

}  // namespace
