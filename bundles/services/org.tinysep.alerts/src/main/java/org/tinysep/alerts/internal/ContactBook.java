package org.tinysep.alerts.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tinysep.api.alert.Notification;

/**
 * The contact list with each contact's ways to reach them, parsed from the {@code contacts} key:
 * comma-separated, each either a plain e-mail address (as before) or {@code Name <scheme:address ...>} with the
 * channels in the order they are tried, e.g. {@code Eva <sms:+4915112345678 push:eva-topic mail:eva@example.org>}.
 * A plain address is its own key; a named contact's key is its name.
 */
final class ContactBook {

    /** One way to reach a contact. */
    record Address(String scheme, String value) {
        @Override
        public String toString() {
            return scheme + ":" + value;
        }
    }

    /** A contact: its key in the escalation list, and its addresses in the order they are tried. */
    record Contact(String key, List<Address> addresses, boolean plain) {
    }

    static final ContactBook EMPTY = new ContactBook(Map.of());
    private static final Pattern MAIL = Pattern.compile("[^@\\s<>,;\"]+@[^@\\s<>,;\"]+");
    private static final Pattern NAMED = Pattern.compile("([^<>]+)<([^<>]*)>");
    private static final Pattern PHONE = Pattern.compile("\\+?[0-9]{3,20}");
    private static final Pattern TOPIC = Pattern.compile("[A-Za-z0-9_-]{1,64}");

    private final Map<String, Contact> contacts;

    private ContactBook(Map<String, Contact> contacts) {
        this.contacts = contacts;
    }

    /** @throws IllegalArgumentException one plain sentence naming the bad entry */
    static ContactBook parse(String value) {
        Map<String, Contact> all = new LinkedHashMap<>();
        for (String part : value.split(",")) {
            String p = part.strip();
            if (p.isEmpty()) {
                continue;
            }
            Contact c = contact(p);
            if (all.putIfAbsent(c.key(), c) != null) {
                throw new IllegalArgumentException("contacts: '" + c.key() + "' is listed twice");
            }
        }
        return new ContactBook(all);
    }

    private static Contact contact(String p) {
        Matcher m = NAMED.matcher(p);
        if (!m.matches()) {
            if (!MAIL.matcher(p).matches()) {
                throw new IllegalArgumentException("contacts: '" + p + "' is neither an e-mail address nor a contact "
                        + "like Eva <sms:+4915112345678 push:eva-topic mail:eva@example.org>");
            }
            return new Contact(p, List.of(new Address(Notification.MAIL, p)), true);
        }
        String name = m.group(1).strip();
        List<Address> addresses = new ArrayList<>();
        for (String token : m.group(2).strip().split("\\s+")) {
            if (!token.isEmpty()) {
                addresses.add(address(name, token));
            }
        }
        if (addresses.isEmpty()) {
            throw new IllegalArgumentException("contacts: " + name + " has no address between < and >");
        }
        return new Contact(name, List.copyOf(addresses), false);
    }

    private static Address address(String name, String token) {
        int colon = token.indexOf(':');
        String scheme = colon < 0 ? Notification.MAIL : token.substring(0, colon).toLowerCase();
        String value = colon < 0 ? token : token.substring(colon + 1);
        boolean ok = switch (scheme) {
            case "mail" -> MAIL.matcher(value).matches();
            case "sms" -> PHONE.matcher(value = phone(value)).matches();
            case "push" -> TOPIC.matcher(value).matches();
            default -> throw new IllegalArgumentException("contacts: " + name + "'s address '" + token + "' has an "
                    + "unknown channel '" + scheme + "' (known: mail, sms, push)");
        };
        if (!ok) {
            throw new IllegalArgumentException("contacts: " + name + "'s " + scheme + " address '" + value + "' is "
                    + "not valid (" + switch (scheme) {
                        case "mail" -> "an e-mail address";
                        case "sms" -> "a phone number like +4915112345678";
                        default -> "a push topic of letters, digits, - and _";
                    } + " is needed)");
        }
        return new Address(scheme, value);
    }

    /** @return the number without spaces, dashes, slashes or brackets, 00 written as + */
    static String phone(String number) {
        String n = number.replaceAll("[\\s\\-/().]", "");
        return n.startsWith("00") ? "+" + n.substring(2) : n;
    }

    /** @return the keys in escalation order */
    List<String> keys() {
        return List.copyOf(contacts.keySet());
    }

    Optional<Contact> get(String key) {
        return Optional.ofNullable(contacts.get(key));
    }

    /** @return the contact with this SMS number (compared without spaces and with 00 as +) */
    Optional<Contact> byPhone(String number) {
        String n = phone(number);
        return contacts.values().stream().filter(c -> c.addresses().stream().anyMatch(a -> a.scheme().equals("sms")
                && a.value().equals(n))).findFirst();
    }
}
