package org.tinysep.mailmanager.internal;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * A real SMTP server on 127.0.0.1 that refuses, for good (550), every recipient whose address starts "nobody", and
 * answers {@code 552 5.2.2 mailbox full} at RCPT for every address starting "full" while {@link #mailboxFull} is set
 * (RFC 5321 4.5.3.1.10: a temporary failure).
 */
final class RefusingSmtpServer extends TestSmtpServer {

    static final String FULL = "552 5.2.2 mailbox full";

    /** Every recipient the server took a message for, once per message. */
    final List<String> acceptedRecipients = new CopyOnWriteArrayList<>();
    volatile boolean mailboxFull = true;

    RefusingSmtpServer() throws IOException {
        super(new ServerSocket(0, 5, InetAddress.getLoopbackAddress()));
        listen();
    }

    @Override
    void session(Socket client) throws IOException {
        converse(client, false, "220 refusing ESMTP");
    }

    @Override
    String answer(String verb, String line, List<String> rcpt, boolean secure) {
        if (verb.equals("RCPT") && line.toLowerCase().contains("<nobody")) {
            return "550 5.1.1 no such user";
        } else if (verb.equals("RCPT") && line.toLowerCase().contains("<full") && mailboxFull) {
            return FULL;
        } else if (verb.equals("DATA") && rcpt.isEmpty()) {
            return "554 5.5.1 no valid recipients";
        }
        return verb.equals("EHLO") ? "250 refusing" : null;
    }

    @Override
    void accept(List<String> rcpt, boolean secure) {
        acceptedRecipients.addAll(rcpt);
    }
}
